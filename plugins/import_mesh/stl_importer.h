#pragma once

#include "spira/plugin/importer.h"

namespace spira::import_mesh {

// import.stl: binary and ASCII STL through spira::readStl (one read, no per-token streams).
class StlImporter final : public ImporterPlugin {
 public:
  std::string id() const override { return "import.stl"; }
  std::string label() const override { return "STL mesh"; }
  std::string description() const override;
  const ParamSchema& schema() const override;
  std::vector<std::string> extensions() const override { return {"stl"}; }
  ImportedMesh read(const std::filesystem::path& file, const ParamSet& params,
                    Progress& progress) const override;
};

}  // namespace spira::import_mesh
