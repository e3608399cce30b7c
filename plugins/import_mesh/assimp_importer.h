#pragma once

#include "spira/plugin/importer.h"

namespace spira::import_mesh {

// Formats read through Assimp (import.obj): one class, configured per format.
class AssimpImporter final : public ImporterPlugin {
 public:
  AssimpImporter(std::string id, std::string label, std::string formatName,
                 std::vector<std::string> extensions);
  std::string id() const override { return id_; }
  std::string label() const override { return label_; }
  std::string description() const override;
  const ParamSchema& schema() const override;
  std::vector<std::string> extensions() const override { return extensions_; }
  ImportedMesh read(const std::filesystem::path& file, const ParamSet& params,
                    Progress& progress) const override;

 private:
  std::string id_, label_, formatName_;
  std::vector<std::string> extensions_;
};

}  // namespace spira::import_mesh
