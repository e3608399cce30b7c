#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_report.h"
#include "spira/mesh/mesh_weld.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/plugin/parameter.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {

// Wall-clock seconds spent in each stage of an import.
struct ImportStageSeconds {
  double read = 0.0;  // the importer's read() plus unit conversion and coordinate checks
  double weld = 0.0;
  double validate = 0.0;
  double total() const { return read + weld + validate; }
};

// A part as the rest of Spira sees it: welded, in millimetres, with its validation report.
// Defects that do not stop an import (zero-area faces, non-manifold edges, open boundaries) are
// listed in `report` with counts and positions; planning decides later what it refuses.
struct ImportedPart {
  TriangleMesh mesh;
  MeshReport report;
  WeldStats weld;
  std::string importerId;
  LengthUnit sourceUnit = LengthUnit::Millimetre;  // the unit the file's coordinates were in
  std::vector<std::string> warnings;
  ImportStageSeconds seconds;
};

// Reads `file` with the importer registered for its extension, converts it to millimetres (the
// unit the format states, else the importer's `unit` parameter), welds and validates it.
// `importerParams` may be null (the importer's defaults) or partial (completed with them).
// Throws IoError for a missing, unreadable or non-regular file; InputError for an unsupported
// extension, invalid parameters, an unreadable format, an empty mesh or non-finite coordinates
// (with their count and first position), and when a third-party reader (OpenCASCADE, run in the
// spira-import helper: see isolated_import.h) crashes or exceeds its limits; Cancelled when
// `progress` is cancelled.
ImportedPart importPart(const PluginRegistry& registry, const std::filesystem::path& file,
                        const ParamSet* importerParams, Progress& progress);

// What importPart does once the importer has read the file: converts `raw` from `unit` to
// millimetres, refuses what cannot be welded (no triangles, corners outside the vertex list,
// non-finite coordinates; `source` names the file), welds and validates. Throws InputError,
// Cancelled.
ImportedPart finishImport(ImportedMesh raw, LengthUnit unit, const std::string& source, Progress& progress);

}  // namespace spira
