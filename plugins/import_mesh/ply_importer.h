#pragma once

#include "spira/plugin/importer.h"

namespace spira::import_mesh {

// import.ply: ASCII and binary PLY through spira::readPly, which checks the header's counts
// against the file before allocating and refuses malformed or truncated files with the place.
class PlyImporter final : public ImporterPlugin {
 public:
  std::string id() const override { return "import.ply"; }
  std::string label() const override { return "PLY mesh"; }
  std::string description() const override;
  const ParamSchema& schema() const override;
  std::vector<std::string> extensions() const override { return {"ply"}; }
  ImportedMesh read(const std::filesystem::path& file, const ParamSet& params,
                    Progress& progress) const override;
};

}  // namespace spira::import_mesh
