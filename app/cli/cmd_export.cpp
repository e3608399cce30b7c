#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "robot_output.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/output_set.h"
#include "spira/document/document.h"
#include "spira/document/plan_report.h"
#include "spira/pipeline/plan_motion.h"
#include "spira/pipeline/planned_path.h"
#include "spira/pipeline/prep_schema.h"
#include "spira/pipeline/sub_paths.h"
#include "spira/planning/joints_csv.h"
#include "spira/planning/plan_files.h"
#include "spira/planning/trajectory_csv_reader.h"
#include "spira/plugin/param_cli.h"
#include "spira/robotcell/cell_file.h"

namespace spira::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kCsvFormat = "csv";

nlohmann::json readPlanReport(const fs::path& planDir)
{
  const fs::path file = planDir / "report.json";
  if (!fs::exists(file)) return nlohmann::json::object();
  return parsePlanReport(readFile(file), file.string());
}

// What is exported: the planned trajectory, the cell it was planned for (if any), the values the
// project stored for the path preparation and the exporter, and the header's names.
struct ExportSource {
  Trajectory trajectory;
  std::optional<CellRecord> cell;
  std::string cellName;  // for the header: a file name or the project's cell name
  std::string partName;
  PlanReportSummary report;
  PlanSettings settings;
  std::vector<bool> plannedCollision;  // from the plan's joints.csv: points it left in collision
  Transform placement =
      Transform::Identity();  // the project's T_world_part: a tilt turns the part on its mount
};

// The collision column (the last) of a joints.csv; empty when the file is missing or does not
// have one row per planned point.
std::vector<bool> collisionColumn(const fs::path& file, size_t points)
{
  std::vector<bool> out;
  if (!fs::exists(file)) return out;
  std::istringstream in(readFile(file));
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line))
    if (!line.empty()) out.push_back(line.substr(line.rfind(',') + 1) == "1");
  if (out.size() != points) out.clear();
  return out;
}

// A .spira project: its process trajectory (the planned path with its channels) and its cell.
ExportSource projectSource(const fs::path& file)
{
  Document doc;
  doc.open(file);
  ExportSource s;
  const PlannedPath planned = plannedPathOf(doc.results());
  if (!planned.trajectory || planned.trajectory->empty())
    throw InputError(
        "the project '" + file.string() + "' holds no planned trajectory",
        "plan it first (Plan in Spira), save it, then export; or run 'spira-cli plan PART -o DIR' "
        "and export DIR");
  s.trajectory = *planned.trajectory;
  s.plannedCollision = planned.collision;
  if (doc.cell()) {
    s.cell = *doc.cell();
    s.cellName = doc.cell()->name;
  }
  s.partName = doc.part() ? (doc.part()->sourcePath.empty() ? doc.part()->name : doc.part()->sourcePath)
                          : file.stem().string();
  if (doc.part()) s.placement = doc.part()->T_world_part;
  // The stage reports carry the plan's key figures (revolutions, heights, length) for the header.
  s.report = planSummaryOf(doc.results()).value_or(PlanReportSummary{});
  if (doc.settings()) s.settings = *doc.settings();
  return s;
}

// A folder written by 'spira-cli plan': trajectory.csv, report.json and the cell named there.
ExportSource planFolderSource(const fs::path& dir)
{
  ExportSource s;
  verifyOutputSet(dir);
  s.report = summarisePlanReport(readPlanReport(dir), (dir / "report.json").string());
  s.partName = s.report.part.empty() ? dir.filename().string() : s.report.part;
  if (!s.report.cellFile.empty()) {
    s.cell = readCellFile(s.report.cellFile);
    s.cellName = s.report.cellFile;
  }
  s.trajectory = readTrajectoryCsv(dir / "trajectory.csv");
  s.plannedCollision = collisionColumn(dir / "joints.csv", s.trajectory.size());
  return s;
}

ExportSource readSource(const fs::path& input)
{
  if (fs::is_directory(input)) return planFolderSource(input);
  if (fs::is_regular_file(input) && input.extension() == ".spira") return projectSource(input);
  throw InputError("'" + input.string() + "' is neither a Spira project (.spira) nor a plan folder",
                   "give a .spira project file or the -o folder of 'spira-cli plan'");
}

// Stored values overridden by the ones given on the command line.
ParamSet merged(ParamSet stored, const ParamSet& given)
{
  for (const auto& [key, value] : given.values()) stored.set(key, value);
  return stored;
}

// The plain export for other tools: the planned trajectory and, with a cell, its solved joints.
int writeCsv(const ExportSource& source, const std::optional<RobotCell>& cell, const fs::path& outDir)
{
  std::vector<OutputFile> files{{"trajectory.csv", trajectoryCsv(source.trajectory)}};
  std::string solvedText;
  if (cell) {
    NullProgress progress;
    const MotionResult solved =
        solveSubPaths(*cell, source.trajectory, motionParamsFor(*cell, MotionSettings{}), progress);
    files.push_back({"joints.csv", jointsCsv(solved.joints)});
    solvedText =
        std::string(" and joints.csv (") + (solved.report.reachable ? "reachable" : "NOT reachable") + ")";
  }
  replaceOutputSet(outDir, OutputKind::Program, files);
  std::cout << "wrote " << (outDir / "trajectory.csv").string() << solvedText << "\n";
  return kExitOk;
}

}  // namespace

int cmdExport(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  Args args = splitArgs(argv);
  const bool help = args.takeSwitch("--help");
  const std::string format = args.takeOption("--format");
  const bool csv = format == kCsvFormat;
  const ExporterPlugin* exporter = format.empty() || csv ? nullptr : &exporterFor(registry, format);
  ParamSet exporterValues, prepValues;
  std::vector<FlagTarget> targets{FlagTarget{std::string(prepSection().name), &prepSchema(), &prepValues}};
  if (exporter) targets.push_back(FlagTarget{exporter->id(), &exporter->schema(), &exporterValues});
  if (help) {
    std::cout
        << "usage: spira-cli export PROJECT.spira|PLAN_DIR --format krl|fanuc_tp|rapid|gcode|csv -o DIR\n"
           "                        [--cell CELL] [parameter flags]\n\n"
           "Writes the robot program of a planned part: a Spira project (.spira, planned and saved)\n"
           "or a folder made by 'spira-cli plan' (PLAN_DIR/trajectory.csv). The path is smoothed and\n"
           "decimated under the tolerances below, solved on the cell (the project's cell, or the\n"
           "plan's --cell from PLAN_DIR/report.json; --cell overrides) and written for the controller.\n"
           "A multi-branch plan gets one arc per sub-path with travel moves between them.\n"
           "Unreachable or colliding points are refused unless --force is given. The exporter's own\n"
           "flags are listed with --format FORMAT --help. --format csv writes the planned\n"
           "trajectory.csv and, with a cell, joints.csv for other tools.\n"
        << paramFlagsHelp(targets);
    return kExitOk;
  }
  const std::string outDir = args.takeOption("-o");
  const std::string cellFile = args.takeOption("--cell");
  args.rest = takeParamFlags(args.rest, targets);
  const auto positional = args.finish("export", 1, 1);
  if (format.empty())
    throw UsageError("'export' needs a program format",
                     "write --format krl, --format fanuc_tp, --format rapid or --format csv");
  if (outDir.empty()) throw UsageError("'export' needs an output folder", "write -o DIR");
  const fs::path input = positional[0];
  if (!fs::exists(input))
    throw InputError("'" + input.string() + "' does not exist",
                     "give a .spira project file or the -o folder of 'spira-cli plan'");
  // Nothing is read or computed before the output folder is known to be writable.
  ensureWritableDirectory(outDir);

  ExportSource source = readSource(input);
  if (!cellFile.empty()) {
    source.cell = readCellFile(cellFile);
    source.cellName = cellFile;
    source.plannedCollision.clear();  // found with another cell's torch and links
  }
  const std::optional<RobotCell> cell =
      source.cell ? std::optional<RobotCell>(RobotCell(cellForPlacement(*source.cell, source.placement)))
                  : std::nullopt;
  if (cell && !cell->canSolve()) throw InputError(cell->ikRefusal(), "choose a cell with a 6-axis arm");
  if (csv) return writeCsv(source, cell, outDir);
  const bool forced = exporterValues.has("force") && exporterValues.getBool("force");
  const bool infeasible = source.report.feasible == false;
  if (infeasible && !forced)
    throw InfeasibleError(
        "the plan is infeasible: " + (source.report.depositSummary.empty()
                                          ? std::string("its report says it is not feasible")
                                          : source.report.depositSummary),
        "change the plan (spira-cli plan prints the change that works), or add --force to "
        "write the program anyway");
  if (!cell && exporter->usesRobotCell())
    std::cerr << "note: no cell: the program's targets are torch poses in the part frame\n";

  ExportJob job;
  job.exporterId = exporter->id();
  job.exporterParams = merged(source.settings.section(exporter->id()), exporterValues);
  job.prep = prepParamsFrom(merged(source.settings.section(std::string(prepSection().name)), prepValues));
  job.cell = cell ? &*cell : nullptr;
  job.plannedCollision = source.plannedCollision;
  job.header = programHeader(source.partName, source.cellName, source.report);
  job.positionerToleranceDeg = source.report.positionerToleranceDeg;
  NullProgress progress;
  const ExportOutcome exported = exportTrajectory(registry, source.trajectory, job, outDir, progress);
  printExportSummary(exported, std::cout);
  return kExitOk;
}

}  // namespace spira::cli
