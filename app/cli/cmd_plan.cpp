#include <chrono>
#include <iomanip>
#include <iostream>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "part_loading.h"
#include "robot_output.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/document/cell_file.h"
#include "spira/pipeline/export_job.h"
#include "spira/pipeline/plan_motion.h"
#include "spira/pipeline/prep_schema.h"
#include "spira/planning/joints_csv.h"
#include "spira/planning/plan_files.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/planner.h"

namespace spira::cli {
namespace {

// Flag targets of 'plan': the spiral and process sections, every decomposer and closure finder.
struct PlanFlags {
  std::map<std::string, ParamSet> values;
  std::vector<FlagTarget> targets;
  explicit PlanFlags(const PluginRegistry& registry)
  {
    values["spiral"];
    values["process"];
    std::vector<const Plugin*> plugins = registry.ofKind(PluginKind::Decomposer);
    for (const Plugin* p : registry.ofKind(PluginKind::ClosureFinder)) plugins.push_back(p);
    for (const Plugin* p : plugins) values[p->id()];
    targets.push_back(FlagTarget{"spiral", &spiralSchema(), &values["spiral"]});
    targets.push_back(FlagTarget{"process", &processSchema(), &values["process"]});
    for (const Plugin* p : plugins) targets.push_back(FlagTarget{p->id(), &p->schema(), &values[p->id()]});
  }
};

void printSummary(const PlanOutput& plan, std::ostream& out)
{
  const SpiralReport& s = plan.spiral.report;
  out << std::fixed << std::setprecision(3);
  const char* kind = plan.topology.partClass == PartClass::Open ? "open" : "closed";
  out << (plan.branching ? "multi-branch" : kind) << " part, " << plan.generatrices.lines.size()
      << " generatrices of " << s.generatrixLengthMin << " .. " << s.generatrixLengthMax << " mm\n";
  if (plan.paths.size() > 1)
    out << plan.paths.size() << " sub-paths (trunk first), one arc start and stop each, split at "
        << plan.branching->saddles.size() << " saddle(s)\n";
  out << s.nRevolutions << " revolutions (" << s.nStartupRevolutions << " start-up, " << s.nLayers
      << " modulated, " << s.nEndRevolutions << " closing), " << s.nPoints << " points, path " << s.pathLength
      << " mm\n";
  out << "deposit height " << s.heightMin << " .. " << s.heightMax << " mm (mean " << s.heightMean
      << " mm) in the modulated layers";
  if (s.rampHeightMax > 0.0)
    out << "; " << s.rampHeightMin << " .. " << s.rampHeightMax << " mm in the start-up and closing ramps";
  out << "\n";
  if (plan.hasClosure)
    out << "closure point (" << plan.closure.point.x() << ", " << plan.closure.point.y() << ", "
        << plan.closure.point.z() << ") mm\n";
  out << "travel speed " << plan.process.travelSpeedMin << " .. " << plan.process.travelSpeedMax
      << " mm/s, build time " << plan.process.buildTime / 60.0 << " min\n";
  out << (plan.feasible() ? "feasible" : "INFEASIBLE") << ": " << s.violations.size()
      << " deposit(s) outside the window, " << plan.process.violations.size()
      << " process-limit violation(s)\n";
  for (const auto& w : plan.warnings) out << "warning: " << w << "\n";
}

}  // namespace

int cmdPlan(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  ImporterFlags importFlags(registry);
  PlanFlags planFlags(registry);
  Args args = splitArgs(argv);
  const bool help = args.takeSwitch("--help");
  const std::string cellFile = args.takeOption("--cell");
  const std::string format = args.takeOption("--export");
  const ExporterPlugin* exporter = format.empty() ? nullptr : &exporterFor(registry, format);
  ParamSet exporterValues, prepValues;
  std::vector<FlagTarget> targets = planFlags.targets;
  targets.insert(targets.end(), importFlags.targets().begin(), importFlags.targets().end());
  if (exporter) {
    targets.push_back(FlagTarget{exporter->id(), &exporter->schema(), &exporterValues});
    targets.push_back(FlagTarget{"prep", &prepSchema(), &prepValues});
  }

  if (help) {
    std::cout
        << "usage: spira-cli plan PART -o DIR [--strategy isovalue] [--lower-loop N] [--substrate-z Z]\n"
           "                       [--cell CELL] [--keep-collisions] [--export krl|fanuc_tp] [--timing]\n"
           "                       [parameter flags]\n\n"
           "Plans one continuous spiral on PART and writes DIR/trajectory.csv and DIR/report.json.\n"
           "With --cell, also checks the torch against the deposit and the substrate (tilting it about\n"
           "the travel direction where it would collide, unless --keep-collisions), solves the robot\n"
           "(and positioner) joints and writes DIR/joints.csv. With --export, writes the robot program\n"
           "into DIR (the flags of the exporter and of the path preparation are listed with\n"
           "--export FORMAT --help).\n"
           "Exit code 4 (files still written) when the plan leaves the process window, or a point is\n"
           "unreachable or collides, or an axis passes its speed limit (see --allow-slowdown).\n"
        << paramFlagsHelp(targets);
    return kOk;
  }
  const std::string outDir = args.takeOption("-o");
  std::string strategy = args.takeOption("--strategy");
  const std::string lowerLoop = args.takeOption("--lower-loop");
  const std::string substrateZ = args.takeOption("--substrate-z");
  const bool timing = args.takeSwitch("--timing");
  const bool keepCollisions = args.takeSwitch("--keep-collisions");
  args.rest = consumeParamFlags(args.rest, targets);
  const auto positional = args.finish("plan", 1, 1);
  if (outDir.empty()) throw UsageError("'plan' needs an output folder", "write -o DIR");
  if (strategy.empty()) strategy = "isovalue";
  if (exporter && cellFile.empty())
    std::cerr << "note: no --cell given: the program's targets are torch poses in the part frame\n";

  ensureWritableDirectory(outDir);
  // Everything the user named is read before the (long) planning starts.
  const std::optional<RobotCell> cell =
      cellFile.empty() ? std::nullopt : std::optional<RobotCell>(RobotCell(readCellFile(cellFile)));
  if (cell && !cell->canSolve()) throw InputError(cell->ikRefusal(), "choose a cell with a 6-axis arm");
  const PrepParams prep = prepParamsFrom(prepValues);

  const auto t0 = std::chrono::steady_clock::now();
  NullProgress progress;
  const ImportedPart part = importFlags.import(positional[0], progress);
  const double importSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  PlanRequest req{part.mesh, part.report};
  req.decomposerId = strategy.find('.') == std::string::npos ? "decomposer." + strategy : strategy;
  try {
    req.lowerLoopOverride = lowerLoop.empty() ? -1 : std::stoi(lowerLoop);
    req.substrateZ = substrateZ.empty() ? 0.0 : std::stod(substrateZ);
  } catch (const std::exception&) {
    throw UsageError("--lower-loop and --substrate-z take numbers", "e.g. --lower-loop 0 --substrate-z 0");
  }
  req.params = planFlags.values;
  PlanOutput plan = planPart(registry, req, progress);
  plan.timings.insert(plan.timings.begin(), {"import", importSeconds});

  nlohmann::json report = planReportJson(plan, strategy);
  bool ok = plan.feasible();
  std::optional<PlanMotion> motion;
  if (cell) {
    const auto tm = std::chrono::steady_clock::now();
    MotionSettings ms = motionSettingsFrom(planFlags.values["process"], planFlags.values["spiral"]);
    ms.substrateZ = req.substrateZ;
    ms.resolveCollisions = !keepCollisions;
    ms.part = &part.mesh;
    motion = solvePlanMotion(*cell, plan.spiral.trajectory, ms, progress);
    plan.timings.push_back(
        {"kinematics", std::chrono::duration<double>(std::chrono::steady_clock::now() - tm).count()});
    for (const auto& [key, value] : motion->report.items()) report[key] = value;
    report["cell_file"] = std::filesystem::absolute(cellFile).lexically_normal().string();
    ok = ok && motion->ok();
  }
  report["timings_s"] = nlohmann::json::object();
  for (const auto& [stage, seconds] : plan.timings) report["timings_s"][stage] = seconds;

  const Trajectory& finalPath = motion ? motion->trajectory : plan.spiral.trajectory;
  writeFileAtomically(std::filesystem::path(outDir) / "trajectory.csv", trajectoryCsv(finalPath));
  if (motion) writeFileAtomically(std::filesystem::path(outDir) / "joints.csv", jointsCsv(motion->joints));
  writeFileAtomically(std::filesystem::path(outDir) / "report.json", report.dump(2) + "\n");
  printSummary(plan, std::cout);
  if (motion) printMotionSummary(motion->report, std::cout);

  if (exporter) {
    ExportJob job;
    job.exporterId = exporter->id();
    job.exporterParams = exporterValues;
    job.prep = prep;
    job.cell = cell ? &*cell : nullptr;
    if (motion)  // unresolved collisions of the plan are flagged in the program (refused unless forced)
      for (const JointPoint& p : motion->joints.points) job.plannedCollision.push_back(p.collision);
    job.header = programHeader(positional[0], cellFile, report);
    const ExportOutcome exported = exportTrajectory(registry, finalPath, job, outDir, progress);
    printExportSummary(exported, std::cout);
    plan.timings.push_back({"export", exported.seconds});
  }
  if (timing)
    for (const auto& [stage, seconds] : plan.timings)
      std::cout << "timing " << stage << ": " << seconds << " s\n";
  std::cout << "wrote " << outDir << "/trajectory.csv" << (motion ? ", joints.csv" : "")
            << " and report.json\n";
  return ok ? kOk : kInfeasible;
}

}  // namespace spira::cli
