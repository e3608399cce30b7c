#pragma once

#include "spira/plugin/exporter.h"

namespace spira {

// export.gcode: a G-code program (.nc) for a gantry or CNC WAAM machine with a two-axis tilting head,
// described by a .machine file (docs/machine-format.md); the head's inverse kinematics is solved here,
// so the export needs no robot cell.
class GcodeExporter final : public ExporterPlugin {
 public:
  GcodeExporter();
  std::string id() const override { return "export.gcode"; }
  std::string label() const override { return "G-code (5-axis head)"; }
  std::string description() const override;
  const ParamSchema& schema() const override { return schema_; }
  std::string fileDescription() const override { return "G-code program (.nc)"; }
  bool usesRobotCell() const override { return false; }
  ExportResult write(const ExportInput& input, const ParamSet& params, const std::filesystem::path& outDir,
                     Progress& progress) const override;

 private:
  ParamSchema schema_;
};

}  // namespace spira
