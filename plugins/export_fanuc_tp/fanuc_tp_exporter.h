#pragma once

#include "spira/plugin/exporter.h"

namespace spira {

// export.fanuc_tp: a FANUC TP program (.ls) for an R-30iB with ArcTool, see fanuc_tp_program.cpp
// for the syntax.
class FanucTpExporter final : public ExporterPlugin {
 public:
  FanucTpExporter();
  std::string id() const override { return "export.fanuc_tp"; }
  std::string label() const override { return "FANUC TP"; }
  std::string description() const override;
  const ParamSchema& schema() const override { return schema_; }
  std::string fileDescription() const override { return "FANUC TP program (.ls)"; }
  ExportResult write(const ExportInput& input, const ParamSet& params, const std::filesystem::path& outDir,
                     Progress& progress) const override;

 private:
  ParamSchema schema_;
};

}  // namespace spira
