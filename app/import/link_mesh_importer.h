#pragma once

#include "spira/plugin/importer.h"

namespace spira {

// import.link_mesh: a robot's link mesh (COLLADA and the other formats robot support packages
// ship) through Assimp, in the spira-import helper only: Assimp is a third-party parser of
// untrusted files, and parts have readers of Spira's own. Coordinates stay in the file's unit
// after its <unit> (metres in ROS packages); the up axis is ignored, as rviz does.
class LinkMeshImporter final : public ImporterPlugin {
 public:
  std::string id() const override { return "import.link_mesh"; }
  std::string label() const override { return "Robot link mesh"; }
  std::string description() const override;
  const ParamSchema& schema() const override;
  std::vector<std::string> extensions() const override { return {"dae"}; }
  ImportedMesh read(const std::filesystem::path& file, const ParamSet& params,
                    Progress& progress) const override;
};

}  // namespace spira
