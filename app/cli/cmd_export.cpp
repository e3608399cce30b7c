#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "robot_output.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/document/cell_file.h"
#include "spira/pipeline/prep_schema.h"
#include "spira/planning/trajectory_csv_reader.h"
#include "spira/plugin/param_cli.h"

namespace spira::cli {
namespace {

namespace fs = std::filesystem;

nlohmann::json readPlanReport(const fs::path& planDir)
{
  const fs::path file = planDir / "report.json";
  if (!fs::exists(file)) return nlohmann::json::object();
  try {
    return nlohmann::json::parse(readFile(file));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + " is not valid JSON: " + e.what(),
                     "plan the part again with spira-cli plan");
  }
}

}  // namespace

int cmdExport(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  Args args = splitArgs(argv);
  const bool help = args.takeSwitch("--help");
  const std::string format = args.takeOption("--format");
  const ExporterPlugin* exporter = format.empty() ? nullptr : &exporterFor(registry, format);
  ParamSet exporterValues, prepValues;
  std::vector<FlagTarget> targets{FlagTarget{"prep", &prepSchema(), &prepValues}};
  if (exporter) targets.push_back(FlagTarget{exporter->id(), &exporter->schema(), &exporterValues});
  if (help) {
    std::cout
        << "usage: spira-cli export PLAN_DIR --format krl|fanuc_tp -o DIR [--cell CELL] [parameter flags]\n\n"
           "Writes the robot program of a plan made by 'spira-cli plan' (PLAN_DIR/trajectory.csv):\n"
           "the path is smoothed and decimated under the tolerances below, solved on the cell (the\n"
           "plan's --cell by default, read from PLAN_DIR/report.json) and written for the controller.\n"
           "Unreachable or colliding points are refused unless --force is given. The exporter's own\n"
           "flags are listed with --format FORMAT --help.\n"
        << paramFlagsHelp(targets);
    return kOk;
  }
  const std::string outDir = args.takeOption("-o");
  std::string cellFile = args.takeOption("--cell");
  args.rest = consumeParamFlags(args.rest, targets);
  const auto positional = args.finish("export", 1, 1);
  if (!exporter)
    throw UsageError("'export' needs a program format", "write --format krl or --format fanuc_tp");
  if (outDir.empty()) throw UsageError("'export' needs an output folder", "write -o DIR");
  const fs::path planDir = positional[0];
  if (!fs::is_directory(planDir))
    throw InputError("'" + planDir.string() + "' is not a plan folder",
                     "give the -o folder of 'spira-cli plan'");
  ensureWritableDirectory(outDir);

  const nlohmann::json report = readPlanReport(planDir);
  if (cellFile.empty()) cellFile = report.value("cell_file", "");
  const std::optional<RobotCell> cell =
      cellFile.empty() ? std::nullopt : std::optional<RobotCell>(RobotCell(readCellFile(cellFile)));
  if (cell && !cell->canSolve()) throw InputError(cell->ikRefusal(), "choose a cell with a 6-axis arm");
  if (!cell) std::cerr << "note: no cell: the program's targets are torch poses in the part frame\n";

  const Trajectory planned = readTrajectoryCsv(planDir / "trajectory.csv");
  ExportJob job;
  job.exporterId = exporter->id();
  job.exporterParams = exporterValues;
  job.prep = prepParamsFrom(prepValues);
  job.cell = cell ? &*cell : nullptr;
  job.header = programHeader(report.value("part", planDir.filename().string()), cellFile, report);
  NullProgress progress;
  const ExportOutcome exported = exportTrajectory(registry, planned, job, outDir, progress);
  printExportSummary(exported, std::cout);
  return kOk;
}

}  // namespace spira::cli
