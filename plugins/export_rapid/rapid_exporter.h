#pragma once

#include "spira/plugin/exporter.h"

namespace spira {

// export.rapid: an ABB RAPID program (.mod, and .pgf when split) for an IRC5 with RobotWare Arc,
// see rapid_program.cpp for the syntax.
class RapidExporter final : public ExporterPlugin {
 public:
  RapidExporter();
  std::string id() const override { return "export.rapid"; }
  std::string label() const override { return "ABB RAPID"; }
  std::string description() const override;
  const ParamSchema& schema() const override { return schema_; }
  std::string fileDescription() const override { return "ABB RAPID module (.mod, .pgf)"; }
  ExportResult write(const ExportInput& input, const ParamSet& params, const std::filesystem::path& outDir,
                     Progress& progress) const override;

 private:
  ParamSchema schema_;
};

}  // namespace spira
