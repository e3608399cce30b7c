#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/path/joint_trajectory.h"
#include "spira/path/trajectory.h"
#include "spira/plugin/plugin.h"

namespace spira {

// What an exporter writes from: the plan's channels (never recomputed) and a few names for the
// header comment block.
struct ExportInput {
  const Trajectory& trajectory;
  const JointTrajectory* joints = nullptr;    // null without a cell
  std::map<std::string, std::string> header;  // "part", "cell", "date", key plan parameters...
};

struct ExportResult {
  std::vector<std::filesystem::path> files;
  std::vector<std::string> warnings;
};

class ExporterPlugin : public Plugin {
 public:
  PluginKind kind() const override { return PluginKind::Exporter; }
  virtual std::string fileDescription() const = 0;  // e.g. "KUKA KRL program (.src/.dat)"
  // False for a machine that is not a robot cell (G-code with its own machine file): the export then
  // solves no cell and the targets are the torch poses in the part frame.
  virtual bool usesRobotCell() const { return true; }
  // Writes into `outDir` (which exists and is writable); all files or none.
  virtual ExportResult write(const ExportInput& input, const ParamSet& params,
                             const std::filesystem::path& outDir, Progress& progress) const = 0;
};

}  // namespace spira
