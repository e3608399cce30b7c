#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/plugin/plugin.h"

namespace spira {

// What an importer reads: raw geometry, before welding and validation (the import service does
// both for every format). `mesh` may be a triangle soup (three fresh vertices per face).
struct ImportedMesh {
  TriangleMesh mesh;
  std::optional<LengthUnit> unit;  // set when the format states its unit; else millimetres are assumed
  // The unit the file itself declares, when the importer already converted `mesh` to `unit`
  // (CAD readers convert while transferring). Reported to the user as the source unit.
  std::optional<LengthUnit> fileUnit;
  std::vector<std::string> warnings;
};

class ImporterPlugin : public Plugin {
 public:
  PluginKind kind() const override { return PluginKind::Importer; }
  // Lower-case extensions without the dot, e.g. {"stl"}.
  virtual std::vector<std::string> extensions() const = 0;
  // Throws InputError/IoError with a one-line cause and a hint for unreadable input.
  virtual ImportedMesh read(const std::filesystem::path& file, const ParamSet& params,
                            Progress& progress) const = 0;
};

}  // namespace spira
