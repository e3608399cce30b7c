#pragma once

#include "occt_import.h"
#include "spira/plugin/importer.h"

namespace spira::import_cad {

// import.step, import.iges and import.brep: one class, configured by format.
class CadImporter final : public ImporterPlugin {
 public:
  explicit CadImporter(CadFormat format);
  std::string id() const override;
  std::string label() const override;
  std::string description() const override;
  const ParamSchema& schema() const override;
  std::vector<std::string> extensions() const override;
  ImportedMesh read(const std::filesystem::path& file, const ParamSet& params,
                    Progress& progress) const override;

 private:
  CadFormat format_;
};

}  // namespace spira::import_cad
