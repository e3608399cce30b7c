#pragma once

#include "spira/plugin/exporter.h"

namespace spira::example {

// The worked example's exporter: the path as plain text, one "x y z travel_speed" row per point
// (mm, mm/s), for a tool that reads point clouds. The header block becomes '#' comment lines.
class XyzExporter : public ExporterPlugin {
 public:
  std::string id() const override { return "export.example_xyz"; }
  std::string label() const override { return "XYZ points (example)"; }
  std::string description() const override { return "The deposition path as x y z travel-speed rows."; }
  std::string fileDescription() const override { return "XYZ point list (.xyz)"; }
  const ParamSchema& schema() const override;
  ExportResult write(const ExportInput& input, const ParamSet& params, const std::filesystem::path& outDir,
                     Progress& progress) const override;
};

}  // namespace spira::example
