#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "part_loading.h"
#include "part_placement.h"
#include "part_plan.h"
#include "robot_output.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/output_set.h"
#include "spira/document/project_file.h"
#include "spira/io/isolated_import.h"
#include "spira/pipeline/document_plan.h"
#include "spira/pipeline/export_job.h"
#include "spira/pipeline/planned_path.h"
#include "spira/pipeline/prep_schema.h"
#include "spira/planning/joints_csv.h"
#include "spira/planning/plan_advice.h"
#include "spira/planning/plan_files.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/planner.h"
#include "spira/planning/settings_sections.h"
#include "spira/plugin/strategy_name.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
#include "substrate_flag.h"

namespace fs = std::filesystem;

namespace spira::cli {
namespace {

void printSummary(const DocumentPlan& done, std::ostream& out)
{
  const PlanOutput& plan = done.output;
  const SpiralReport& s = plan.spiral.report;
  out << std::fixed << std::setprecision(3);
  const char* kind = plan.topology.partClass == PartClass::Open ? "open" : "closed";
  out << (plan.branching ? "multi-branch" : kind) << " part, " << done.results.generatrices->lines.size()
      << " generatrices of " << s.generatrixLengthMin << " .. " << s.generatrixLengthMax << " mm\n";
  if (plan.paths.size() > 1)
    out << plan.paths.size() << " sub-paths (trunk first), one arc start and stop each, split at "
        << plan.branching->saddles.size() << " saddle(s)\n";
  if (plan.layers) {
    const LayerStats& l = *plan.layers;
    out << l.layers << " layers at " << l.deltaMin << " .. " << l.deltaMax
        << " mm from the layer below, largest kink " << std::setprecision(1) << l.maxKinkDeg << " deg, "
        << l.arcStarts << " arc start(s), end " << (l.end == "modulate" ? "modulated" : "truncated") << "\n"
        << std::setprecision(3);
  }
  if (plan.layers && plan.layers->output == "layers")
    out << s.nPoints << " points in " << plan.layers->layers << " layers, path " << s.pathLength << " mm\n";
  else
    out << s.nRevolutions << " revolutions (" << s.nStartupRevolutions << " start-up, " << s.nLayers
        << " modulated, " << s.nEndRevolutions << " closing), " << s.nPoints << " points, path "
        << s.pathLength << " mm\n";
  out << "deposit height " << s.heightMin << " .. " << s.heightMax << " mm (mean " << s.heightMean
      << " mm) in the modulated layers";
  if (s.rampHeightMax > 0.0)
    out << "; " << s.rampHeightMin << " .. " << s.rampHeightMax << " mm in the start-up and closing ramps";
  out << "\n";
  if (plan.hasClosure)
    out << "closure point (" << plan.closure.point.x() << ", " << plan.closure.point.y() << ", "
        << plan.closure.point.z() << ") mm\n";
  out << "travel speed " << plan.process.travelSpeedMin << " .. " << plan.process.travelSpeedMax
      << " mm/s, build time " << plan.process.buildTime / 60.0 << " min";
  if (plan.process.dwells > 0)
    out << " with " << plan.process.dwells << " dwell(s) of " << plan.process.dwellTime << " s in all";
  out << "\n";
  const DepositCheckReport& d = plan.deposits;
  out << "deposit check: " << d.pointsChecked << " arc-on points, measured height " << d.heightMin << " .. "
      << d.heightMax << " mm";
  if (d.coverageChecked) out << ", " << 100.0 * (1.0 - d.uncoveredFraction()) << " % of the surface covered";
  out << "\n"
      << (plan.feasible() ? "feasible" : "INFEASIBLE") << ": " << d.summary() << "; " << s.violations.size()
      << " planned deposit(s) outside the window, " << plan.process.violations.size()
      << " process-limit violation(s)\n";
  for (const auto& w : plan.warnings) out << "warning: " << w << "\n";
}

}  // namespace

int cmdPlan(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  PartPlanFlags partFlags(registry);
  Args args = splitArgs(argv);
  for (size_t i = 0; i < args.rest.size(); ++i)
    if (fs::path(args.rest[i]).extension() == kProjectExtension && (i == 0 || args.rest[i - 1] != "-o") &&
        std::find(args.rest.begin(), args.rest.end(), "--help") == args.rest.end())
      return cmdPlanProject(args, args.rest[i]);
  const bool help = args.takeSwitch("--help");
  const std::string cellFile = args.takeOption("--cell");
  const std::string format = args.takeOption("--export");
  const ExporterPlugin* exporter = format.empty() ? nullptr : &exporterFor(registry, format);
  ParamSet exporterValues, prepValues;
  std::vector<FlagTarget> targets = partFlags.targets();
  if (exporter) {
    targets.push_back(FlagTarget{exporter->id(), &exporter->schema(), &exporterValues});
    targets.push_back(FlagTarget{std::string(prepSection().name), &prepSchema(), &prepValues});
  }

  if (help) {
    std::cout
        << "usage: spira-cli plan PART -o DIR [--strategy isovalue] [--lower-loop N] [--substrate-z Z] "
           "[--drop] [--level-base]\n"
           "                       [--substrate FILE|cylinder:R[,AXIS[,LENGTH]]]\n"
           "       spira-cli plan PROJECT.spira -o DIR [--save]\n"
           "                       [--no-mid-surface]\n"
           "                       [--cell CELL] [--keep-collisions] [--export krl|fanuc_tp|rapid|gcode]\n"
           "                       [--timing] [parameter flags]\n\n"
           "Plans one continuous spiral on PART and writes DIR/trajectory.csv and DIR/report.json.\n"
           "With --cell, also checks the torch against the deposit and the substrate (tilting it about\n"
           "the travel direction where it would collide, unless --keep-collisions), solves the robot\n"
           "(and positioner) joints and writes DIR/joints.csv. With --export, writes the robot program\n"
           "into DIR (the flags of the exporter and of the path preparation are listed with\n"
           "--export FORMAT --help).\n"
           "The plan is feasible when the deposit check (docs/deposit-check.md) finds every bead of the\n"
           "path supported inside the process window, no jump with the arc on and the surface covered.\n"
           "Exit code 4 when it is not, or a point is unreachable or collides, or an axis passes its\n"
           "speed limit (see --allow-slowdown): trajectory.csv and report.json are still written (to\n"
           "inspect), the robot program is not.\n"
           "A watertight thin-walled solid is planned on its mid-surface (its wall thickness is measured\n"
           "and compared with the bead width); --no-mid-surface refuses it instead. A solid body that is\n"
           "not a thin wall is refused (docs/thin-walled-solids.md).\n"
           "A saved project is planned as Spira plans it, with its part, placement, substrate, cell and\n"
           "settings (no other flags); --save stores the plan in the project (export it with\n"
           "'spira-cli export PROJECT.spira').\n\n"
        << kPlacementHelp << kSubstrateFlagHelp << paramFlagsHelp(targets);
    return kExitOk;
  }
  const std::string outDir = args.takeOption("-o");
  partFlags.take(args);
  partFlags.substrate = args.takeOption("--substrate");
  const std::string substrateScan = args.takeOption("--substrate-scan");
  if (!substrateScan.empty()) {
    if (!partFlags.substrate.empty())
      throw UsageError("--substrate and --substrate-scan both name the surface to build on",
                       "give one of them");
    partFlags.substrate = kScanPrefix + substrateScan;
  }
  if (!partFlags.substrate.empty() && partFlags.placement.drop)
    throw UsageError(
        "--drop moves the part onto the plate, and --substrate (or --substrate-scan) builds it on another "
        "surface",
        "leave out --drop: with --substrate the part's base edge must already lie on the substrate");
  const bool timing = args.takeSwitch("--timing");
  const bool keepCollisions = args.takeSwitch("--keep-collisions");
  args.rest = takeParamFlags(args.rest, targets);
  const auto positional = args.finish("plan", 1, 1);
  if (outDir.empty()) throw UsageError("'plan' needs an output folder", "write -o DIR");
  if (exporter && cellFile.empty() && exporter->usesRobotCell())
    std::cerr << "note: no --cell given: the program's targets are torch poses in the part frame\n";

  ensureWritableDirectory(outDir);
  // Everything the user named is read before the (long) planning starts.
  std::shared_ptr<const CellRecord> cellRecord;
  std::optional<RobotCell> cell;  // checked now, and what the program is solved on
  if (!cellFile.empty()) {
    cellRecord = std::make_shared<const CellRecord>(readCellFile(cellFile));
    cell.emplace(*cellRecord);
    if (!cell->canSolve()) throw InputError(cell->ikRefusal(), "choose a cell with a 6-axis arm");
    // The robot's link meshes are read in the import helper after planning: it loads meanwhile.
    prestartImportHelper();
  }
  const PrepParams prep = prepParamsFrom(prepValues);

  NullProgress progress;
  PlannedPart part = planPartFile(registry, positional[0], partFlags, cellRecord, keepCollisions, progress);
  DocumentPlan& plan = part.plan;
  nlohmann::json& report = plan.report;
  if (cellRecord) report["cell_file"] = std::filesystem::absolute(cellFile).lexically_normal().string();

  const Results& r = plan.results;
  const PlannedPath planned = plannedPathOf(r);
  const Trajectory& finalPath = *planned.trajectory;
  std::vector<OutputFile> planFiles{{"trajectory.csv", trajectoryCsv(finalPath)}};
  if (r.kinematics) planFiles.push_back({"joints.csv", jointsCsv(r.kinematics->joints)});
  planFiles.push_back({"report.json", report.dump(2) + "\n"});
  replaceOutputSet(outDir, OutputKind::Plan, planFiles);
  printSummary(plan, std::cout);
  if (plan.advice) std::cout << "advice: " << plan.advice->text() << "\n";
  if (r.kinematics && r.reports.kinematics) printMotionSummary(r.reports.kinematics->motion, std::cout);

  const bool forced = exporterValues.has("force") && exporterValues.getBool("force");
  if (exporter && !plan.feasible && !forced) {
    std::cout << "the robot program was not written: the deposit check rejects the path (add --force to "
                 "write it anyway, each rejected point then carries a warning comment)\n";
  } else if (exporter) {
    ExportJob job;
    job.exporterId = exporter->id();
    job.exporterParams = exporterValues;
    job.prep = prep;
    job.cell = cell ? &*cell : nullptr;
    job.plannedCollision = planned.collision;  // flagged in the program, refused unless forced
    const PlanReportSummary summary = planSummaryOf(r).value_or(PlanReportSummary{});
    job.header = programHeader(positional[0], cellFile, summary);
    job.positionerToleranceDeg = summary.positionerToleranceDeg;
    const ExportOutcome exported = exportTrajectory(registry, finalPath, job, outDir, progress);
    printExportSummary(exported, std::cout);
    report["timings_s"]["export"] = exported.seconds;
  }
  if (timing)
    for (const auto& [stage, seconds] : report["timings_s"].items())
      std::cout << "timing " << stage << ": " << seconds.get<double>() << " s\n";
  std::cout << "wrote " << outDir << "/trajectory.csv" << (r.kinematics ? ", joints.csv" : "")
            << " and report.json\n";
  return plan.feasible && plan.motionOk ? kExitOk : kExitInfeasible;
}

}  // namespace spira::cli
