#pragma once

#include <string>
#include <vector>

#include "spira/planning/planner.h"

namespace spira {

// A change of settings that was planned and found feasible, or why none was.
struct PlanAdvice {
  bool found = false;
  std::string change;              // "widen the window to 1.60 .. 2.40 mm", "use the geodesic strategy"
  std::string flags;               // the spira-cli flags that make it: "--h-min 1.6 --h-max 2.4"
  std::vector<std::string> tried;  // each change tried that did not plan feasibly, and why
  // One sentence for a message: the change and its flags, or what was tried.
  std::string text() const;
};

// Looks for the smallest change that plans `request`'s part feasibly, planning each candidate in
// turn: the window the deposit check measured (when only thin or thick beads failed), then every
// other strategy at the same window, then every other strategy at the measured window. `failed`
// is the infeasible plan (null when the strategy refused the part). At most `maxPlans` plans.
PlanAdvice adviseChange(const PluginRegistry& registry, const PlanRequest& request, const PlanOutput* failed,
                        Progress& progress, int maxPlans = 4);

}  // namespace spira
