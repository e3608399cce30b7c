#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "spira/planning/planner.h"

namespace spira {

// One strategy's result on a part: a CTPP plan with one decomposer, or the planar 2.5D baseline.
struct StrategyOutcome {
  std::string strategy;  // decomposer id, or "planar_2.5d"
  std::string kind;      // "ctpp" or "planar"
  bool ran = false;      // false: it failed, `failure` says why
  std::string failure;
  bool feasible = false;  // every deposit in the window (and, for CTPP, Eq. 3.6)
  double runtime = 0.0;   // s, wall clock, field and decomposition included
  double generatrixLengthMin = 0.0, generatrixLengthMax = 0.0;   // CTPP only
  double depositMin = 0.0, depositMax = 0.0, depositMean = 0.0;  // mm, over every point
  size_t outside = 0;                                            // points whose deposit is outside the window
  int revolutions = 0;  // CTPP: revolutions of all sub-paths; planar: layers
  size_t paths = 0;     // CTPP sub-paths (1 for a mono-branch part)
  int arcStarts = 0;    // arcs the path is laid in: sub-paths and pieces (planar: layers)
  // Laid in layers (constant distance): the largest turning angle within a layer, deg; -1: not measured.
  double maxKinkDeg = -1.0;
  std::vector<Vec3> points;  // the path (CTPP) or the layers' contour points (planar)
  std::vector<double> heights;
};

struct Comparison {
  double h = 0.0, hMin = 0.0, hMax = 0.0, tolerance = 0.0;  // the one process window, mm
  std::vector<StrategyOutcome> strategies;                  // decomposers in registry order, then planar
};

// Plans `request`'s part with every registered decomposer (request.decomposerId is ignored; the
// rest of the request, process window included, is shared) and slices it with the planar
// baseline (planar_baseline.h) at the same h and window. A strategy that refuses the part or fails
// is listed with its reason; only cancellation and invalid settings (a contradictory window) stop
// the comparison.
Comparison compareStrategies(const PluginRegistry& registry, const PlanRequest& request, Progress& progress);

// DIR/compare.json: the window and, per strategy, feasible, failure, generatrix lengths and their
// spread, deposit min/max/mean, points outside the window, revolutions, sub-paths, arc starts, the
// largest layer kink (constant distance) and runtime.
nlohmann::json comparisonJson(const Comparison& comparison);
// DIR/compare.csv: strategy,x,y,z,height per point (mm).
std::string comparisonCsv(const Comparison& comparison);
void writeComparisonFiles(const Comparison& comparison, const std::filesystem::path& dir);

}  // namespace spira
