#include <iomanip>
#include <iostream>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "part_loading.h"
#include "spira/base/atomic_file.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/strategy_compare.h"

namespace spira::cli {
namespace {

// The flags 'plan' takes for the plan itself: the spiral and process sections, every decomposer
// and closure finder (each strategy reads its own).
struct CompareFlags {
  std::map<std::string, ParamSet> values;
  std::vector<FlagTarget> targets;
  explicit CompareFlags(const PluginRegistry& registry)
  {
    std::vector<const Plugin*> plugins = registry.ofKind(PluginKind::Decomposer);
    for (const Plugin* p : registry.ofKind(PluginKind::ClosureFinder)) plugins.push_back(p);
    values["spiral"];
    values["process"];
    for (const Plugin* p : plugins) values[p->id()];
    targets.push_back(FlagTarget{"spiral", &spiralSchema(), &values["spiral"]});
    targets.push_back(FlagTarget{"process", &processSchema(), &values["process"]});
    for (const Plugin* p : plugins) targets.push_back(FlagTarget{p->id(), &p->schema(), &values[p->id()]});
  }
};

void printTable(const Comparison& c, std::ostream& out)
{
  out << std::fixed << std::setprecision(3) << "window " << c.hMin << " .. " << c.hMax << " mm (h = " << c.h
      << " mm)\n";
  for (const StrategyOutcome& s : c.strategies) {
    out << s.strategy << ": ";
    if (!s.ran) {
      out << "failed: " << s.failure << "\n";
      continue;
    }
    out << (s.feasible ? "feasible" : "INFEASIBLE") << ", deposit " << s.depositMin << " .. " << s.depositMax
        << " mm (mean " << s.depositMean << "), " << s.outside << " of " << s.points.size()
        << " points outside the window, " << s.revolutions
        << (s.kind == "planar" ? " layers" : " revolutions");
    if (s.kind == "ctpp")
      out << ", generatrices " << s.generatrixLengthMin << " .. " << s.generatrixLengthMax << " mm";
    out << ", " << s.runtime << " s\n";
  }
}

}  // namespace

int cmdCompare(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  ImporterFlags importFlags(registry);
  CompareFlags flags(registry);
  Args args = splitArgs(argv);
  std::vector<FlagTarget> targets = flags.targets;
  targets.insert(targets.end(), importFlags.targets().begin(), importFlags.targets().end());
  if (args.takeSwitch("--help")) {
    std::cout
        << "usage: spira-cli compare PART -o DIR [--lower-loop N] [--substrate-z Z] [parameter flags]\n\n"
           "Plans PART with every decomposition strategy in the same process window, slices it\n"
           "with horizontal planes every h as the 2.5D reference (each point's deposit is its\n"
           "distance to the layer below; the upper edge is the last layer), and writes\n"
           "DIR/compare.json (per strategy: feasible or why it failed, generatrix lengths,\n"
           "deposit min/max/mean, points outside the window, revolutions, runtime) and\n"
           "DIR/compare.csv (strategy,x,y,z,height per point). A strategy that fails is listed,\n"
           "not an error.\n"
        << paramFlagsHelp(targets);
    return kOk;
  }
  const std::string outDir = args.takeOption("-o");
  const std::string lowerLoop = args.takeOption("--lower-loop");
  const std::string substrateZ = args.takeOption("--substrate-z");
  args.rest = consumeParamFlags(args.rest, targets);
  const auto positional = args.finish("compare", 1, 1);
  if (outDir.empty()) throw UsageError("'compare' needs an output folder", "write -o DIR");
  ensureWritableDirectory(outDir);

  NullProgress progress;
  const ImportedPart part = importFlags.import(positional[0], progress);
  PlanRequest request{part.mesh, part.report};
  try {
    request.lowerLoopOverride = lowerLoop.empty() ? -1 : std::stoi(lowerLoop);
    request.substrateZ = substrateZ.empty() ? 0.0 : std::stod(substrateZ);
  } catch (const std::exception&) {
    throw UsageError("--lower-loop and --substrate-z take numbers", "e.g. --lower-loop 0 --substrate-z 0");
  }
  request.params = flags.values;
  const Comparison comparison = compareStrategies(registry, request, progress);
  writeComparisonFiles(comparison, outDir);
  printTable(comparison, std::cout);
  std::cout << "wrote " << outDir << "/compare.json and compare.csv\n";
  return kOk;
}

}  // namespace spira::cli
