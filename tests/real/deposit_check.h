#pragma once

#include <array>
#include <string>
#include <vector>

#include "real/vec3.h"

namespace spira::test::real {

// One trajectory point as the checker reads it from trajectory.csv: position, build direction
// (the torch axis), sub-path index and arc flag. Nothing the planner says about itself.
struct PathPoint {
  V3 p;
  V3 b{0, 0, 1};
  int path = 0;
  bool arc = true;
};

// The process window and the substrate the plan is judged against (docs/deposit-check.md).
struct CheckSettings {
  double hMin = 1.8;
  double hMax = 2.2;
  double tol = 0.01;  // mm
  double beadWidth = 5.2;
  double substrateZ = 0.0;
};

enum class Flag { Unsupported, Thin, Thick, BelowDeposit, Jump };
const char* flagName(Flag f);

struct Offender {
  size_t index = 0;
  Flag flag = Flag::Unsupported;
  double height = 0;  // measured H (NaN where nothing lies below)
  V3 p;
};

using Triangle = std::array<V3, 3>;

struct CheckResult {
  size_t checked = 0;  // arc-on points
  size_t unsupported = 0, thin = 0, thick = 0, below = 0, jump = 0;
  double heightMin = 0, heightMax = 0, heightMean = 0;  // over the points with a measured height
  std::vector<Offender> firstOffenders;                 // at most 10, in path order
  bool coverageChecked = false;
  double surfaceArea = 0, uncoveredArea = 0, maxDistance = 0;
  double uncoveredFraction() const { return surfaceArea > 0 ? uncoveredArea / surfaceArea : 0.0; }
  size_t flagged() const { return unsupported + thin + thick + below + jump; }
  // Feasible: no arc-on point flagged and at most 0.5 % of the surface uncovered.
  bool feasible() const { return flagged() == 0 && uncoveredFraction() <= 0.005; }
  // One line of counts: unsupported, thin, thick, below, jump and the uncovered share.
  std::string counts() const;
  // The counts, the measured heights, the coverage and the first offending points.
  std::string summary() const;
};

// Judges `points` by the rules of docs/deposit-check.md, written here on their own: brute force
// over a uniform grid, sharing no code with the product. `surface` (mm, may be empty) adds the
// coverage figures.
CheckResult checkDeposit(const std::vector<PathPoint>& points, const CheckSettings& settings,
                         const std::vector<Triangle>& surface = {});

}  // namespace spira::test::real
