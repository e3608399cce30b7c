#include <algorithm>
#include <iomanip>
#include <iostream>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "part_loading.h"
#include "part_placement.h"
#include "spira/base/atomic_file.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/settings_sections.h"
#include "spira/planning/strategy_compare.h"

namespace spira::cli {
namespace {

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
    if (s.kind == "ctpp" && s.maxKinkDeg < 0.0)
      out << ", generatrices " << s.generatrixLengthMin << " .. " << s.generatrixLengthMax << " mm";
    out << ", " << s.arcStarts << " arc start(s)";
    if (s.maxKinkDeg >= 0.0)
      out << std::setprecision(1) << ", layer kink up to " << s.maxKinkDeg << " deg" << std::setprecision(3);
    out << ", " << s.runtime << " s\n";
  }
}

}  // namespace

int cmdCompare(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  ImporterFlags importFlags(registry);
  PlanFlags flags(registry);
  Args args = splitArgs(argv);
  std::vector<FlagTarget> targets = flags.targets;
  targets.insert(targets.end(), importFlags.targets().begin(), importFlags.targets().end());
  if (args.takeSwitch("--help")) {
    std::cout
        << "usage: spira-cli compare PART -o DIR [--lower-loop N] [--substrate-z Z] [--drop] [--level-base] "
           "[parameter flags]\n\n"
           "Plans PART with every decomposition strategy in the same process window, slices it\n"
           "with horizontal planes every h as the 2.5D reference (each point's deposit is its\n"
           "distance to the layer below; the upper edge is the last layer), and writes\n"
           "DIR/compare.json (per strategy: feasible or why it failed, generatrix lengths,\n"
           "deposit min/max/mean, points outside the window, revolutions, arc starts, layer kinks,\n"
           "runtime) and\n"
           "DIR/compare.csv (strategy,x,y,z,height per point). A strategy that fails is listed,\n"
           "not an error; exit code 4 when no strategy plans the part feasibly.\n\n"
        << kPlacementHelp << paramFlagsHelp(targets);
    return kExitOk;
  }
  const std::string outDir = args.takeOption("-o");
  const PartPlacement placement = PartPlacement::take(args);
  args.rest = takeParamFlags(args.rest, targets);
  const auto positional = args.finish("compare", 1, 1);
  if (outDir.empty()) throw UsageError("'compare' needs an output folder", "write -o DIR");
  ensureWritableDirectory(outDir);

  NullProgress progress;
  ImportedPart part = importFlags.import(positional[0], progress);
  for (const auto& w : part.warnings) std::cerr << "warning: " << w << "\n";
  placement.apply(part);
  PlanRequest request{part.mesh, part.report};
  request.lowerLoopOverride = placement.lowerLoop;
  request.substrateZ = placement.substrateZ;
  request.params = flags.values;
  const Comparison comparison = compareStrategies(registry, request, progress);
  writeComparisonFiles(comparison, outDir);
  printTable(comparison, std::cout);
  std::cout << "wrote " << outDir << "/compare.json and compare.csv\n";
  const bool anyFeasible =
      std::any_of(comparison.strategies.begin(), comparison.strategies.end(),
                  [](const StrategyOutcome& s) { return s.kind == "ctpp" && s.feasible; });
  if (!anyFeasible)
    std::cerr << "no strategy plans this part feasibly: see each strategy's failure above and 'spira-cli "
                 "plan PART --strategy S' for the points the deposit check rejects\n";
  return anyFeasible ? kExitOk : kExitInfeasible;
}

}  // namespace spira::cli
