#include <chrono>
#include <iomanip>
#include <iostream>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "part_loading.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
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
  out << (plan.topology.partClass == PartClass::Open ? "open" : "closed") << " part, "
      << plan.generatrices.lines.size() << " generatrices of " << s.generatrixLengthMin << " .. "
      << s.generatrixLengthMax << " mm\n";
  out << s.nRevolutions << " revolutions (" << s.nStartupRevolutions << " start-up, " << s.nLayers
      << " modulated, " << s.nEndRevolutions << " closing), " << s.nPoints << " points, path " << s.pathLength
      << " mm\n";
  out << "deposit height " << s.heightMin << " .. " << s.heightMax << " mm (mean " << s.heightMean
      << " mm)\n";
  if (plan.hasClosure)
    out << "closure point (" << plan.closure.point.x() << ", " << plan.closure.point.y() << ", "
        << plan.closure.point.z() << ") mm\n";
  out << "travel speed " << plan.process.travelSpeedMin << " .. " << plan.process.travelSpeedMax
      << " mm/s, build time " << plan.process.buildTime / 60.0 << " min\n";
  out << (plan.feasible() ? "feasible" : "INFEASIBLE") << ": " << s.modulatedViolations
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
  std::vector<FlagTarget> targets = planFlags.targets;
  targets.insert(targets.end(), importFlags.targets().begin(), importFlags.targets().end());

  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout
        << "usage: spira-cli plan PART -o DIR [--strategy isovalue] [--lower-loop N] [--substrate-z Z]\n"
           "                       [--timing] [parameter flags]\n\n"
           "Plans one continuous spiral on PART and writes DIR/trajectory.csv and DIR/report.json.\n"
           "Exit code 4 (report still written) when the plan leaves the process window or limits.\n"
        << paramFlagsHelp(targets);
    return kOk;
  }
  const std::string outDir = args.takeOption("-o");
  std::string strategy = args.takeOption("--strategy");
  const std::string lowerLoop = args.takeOption("--lower-loop");
  const std::string substrateZ = args.takeOption("--substrate-z");
  const bool timing = args.takeSwitch("--timing");
  args.rest = consumeParamFlags(args.rest, targets);
  const auto positional = args.finish("plan", 1, 1);
  if (outDir.empty()) throw UsageError("'plan' needs an output folder", "write -o DIR");
  if (strategy.empty()) strategy = "isovalue";

  ensureWritableDirectory(outDir);
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
  writePlanFiles(plan, strategy, outDir);
  printSummary(plan, std::cout);
  if (timing)
    for (const auto& [stage, seconds] : plan.timings)
      std::cout << "timing " << stage << ": " << seconds << " s\n";
  std::cout << "wrote " << outDir << "/trajectory.csv and " << outDir << "/report.json\n";
  return plan.feasible() ? kOk : kInfeasible;
}

}  // namespace spira::cli
