#pragma once

#include "spira/plugin/exporter.h"

namespace spira {

// export.krl: a KUKA KRL program (.src/.dat) for a KR C4, see krl_program.cpp for the syntax.
class KrlExporter final : public ExporterPlugin {
 public:
  KrlExporter();
  std::string id() const override { return "export.krl"; }
  std::string label() const override { return "KUKA KRL"; }
  std::string description() const override;
  const ParamSchema& schema() const override { return schema_; }
  std::string fileDescription() const override { return "KUKA KRL program (.src/.dat)"; }
  ExportResult write(const ExportInput& input, const ParamSet& params, const std::filesystem::path& outDir,
                     Progress& progress) const override;

 private:
  ParamSchema schema_;
};

}  // namespace spira
