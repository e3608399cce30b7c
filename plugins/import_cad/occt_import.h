#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira::import_cad {

enum class CadFormat { Step, Iges, Brep };

struct TessellationSettings {
  double linearDeflection = 0.1;    // largest chord distance, in the unit the shape comes out in
  double angularDeflection = 0.17;  // rad
};

// A tessellated CAD file. STEP and IGES come out in millimetres whatever unit the file declares
// (`fileUnit` reports it when Spira knows it); BREP stores no unit and comes out as written.
struct CadMesh {
  TriangleMesh mesh;  // indexed per CAD face: vertices shared inside a face, not across faces
  std::optional<LengthUnit> fileUnit;
  std::vector<std::string> warnings;
};

// Reads, transfers and tessellates with OpenCASCADE. Faces keep the orientation of the solid or
// shell (reversed faces are flipped) and their locations are applied. Throws InputError for
// unreadable or empty files and for a STEP file that lost more than 5 % of the faces it declares
// (fewer: a warning), std::bad_alloc when OpenCASCADE runs out of memory, Cancelled when
// `progress` is cancelled.
CadMesh importCadFile(const std::filesystem::path& file, CadFormat format,
                      const TessellationSettings& settings, Progress& progress);

}  // namespace spira::import_cad
