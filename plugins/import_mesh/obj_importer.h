#pragma once

#include "spira/plugin/importer.h"

namespace spira::import_mesh {

// import.obj: Wavefront OBJ through spira::readObj, which reads geometry only, grows with the
// bytes rather than with numbers in them, and refuses malformed files with the line.
class ObjImporter final : public ImporterPlugin {
 public:
  std::string id() const override { return "import.obj"; }
  std::string label() const override { return "Wavefront OBJ mesh"; }
  std::string description() const override;
  const ParamSchema& schema() const override;
  std::vector<std::string> extensions() const override { return {"obj"}; }
  ImportedMesh read(const std::filesystem::path& file, const ParamSet& params,
                    Progress& progress) const override;
};

}  // namespace spira::import_mesh
