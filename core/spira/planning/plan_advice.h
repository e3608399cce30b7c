#pragma once

#include <string>
#include <vector>

#include "spira/path/too_short_error.h"
#include "spira/planning/part_topology.h"
#include "spira/planning/planner.h"

namespace spira {

// A change of settings that was planned and found feasible, or why none was.
struct PlanAdvice {
  bool found = false;
  std::string change;              // "widen the window to 1.60 .. 2.40 mm", "use the geodesic strategy"
  std::string flags;               // the spira-cli flags that make it: "--h-min 1.6 --h-max 2.4"
  std::vector<std::string> tried;  // each change tried that did not plan feasibly, and why
  // Why no change of settings can plan it, when that is known (a junction's crotch, crotch_flags.h).
  std::string cause;
  bool causeExplainsMost = false;  // it holds at least half the flagged points
  // One sentence for a message: the change (with its spira-cli flags when `withFlags`), or what
  // was tried.
  std::string text(bool withFlags = true) const;
};

// Looks for the smallest change that plans `request`'s part feasibly, planning each candidate in
// turn: the window the deposit check measured (when only thin or thick beads failed), then every
// other strategy at the same window, then every other strategy at the measured window. `failed`
// is the infeasible plan (null when the strategy refused the part). At most `maxPlans` plans.
// When none plans and `failed` has flags around a junction's crotch, `cause` says so.
PlanAdvice adviseChange(const PluginRegistry& registry, const PlanRequest& request, const PlanOutput* failed,
                        Progress& progress, int maxPlans = 4);

// For a part refused because a wall (or a branch's) is too short for the start-up, one layer and
// the termination at this h: every ramp height scales with h, so the largest h on a 0.05 mm grid
// that leaves room (the window scaled with it) is planned and checked. Nothing is found when that
// h is below kThinnestAdvisedDeposit or its plan is not feasible (then `tried` says why).
PlanAdvice adviseSmallerDeposit(const PluginRegistry& registry, const PlanRequest& request,
                                const TooShortError& refusal, Progress& progress);

// For a part refused because its base edge is not level: the part cut level through the edge's
// highest point and stood on the substrate (level_base.h), planned and checked. `tried` says how
// the levelled part fails when it does.
PlanAdvice adviseLevelBase(const PluginRegistry& registry, const PlanRequest& request,
                           const BaseNotLevelError& refusal, Progress& progress);

// planPart(), and for a part it refuses, the refusal again with the change that plans it in its
// hint once one was planned and checked feasible (a smaller h for a wall too short for its ramps,
// the levelled base, another strategy), or with what was tried. The CLI and the desktop app plan
// through it.
PlanOutput planOrAdvise(const PluginRegistry& registry, const PlanRequest& request, Progress& progress);

// No WAAM process lays a steady bead thinner than this (mm): a smaller h is not advice.
constexpr double kThinnestAdvisedDeposit = 0.5;

}  // namespace spira
