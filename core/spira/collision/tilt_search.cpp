#include "spira/collision/tilt_search.h"

#include <algorithm>
#include <limits>

namespace spira {

double clearingTilt(const TorchCollisionChecker& checker, size_t i, int sign, double fromMagnitude,
                    const ResolveSettings& s)
{
  const double inf = std::numeric_limits<double>::infinity();
  double fallback = inf;
  double previous = fromMagnitude;  // known to collide
  // Successive tilts of one point mostly hit the same bead: try it first (same answers, cheaper).
  uint32_t hint = CapsuleBvh::kAll;
  const auto collides = [&](double tilt) { return checker.collides(i, tilt, hint); };
  while (previous < s.maxTiltRad) {
    const double m = std::min(previous + s.searchStepRad, s.maxTiltRad);
    if (collides(sign * m)) {
      previous = m;
      continue;
    }
    double lo = previous, hi = m;  // lo collides, hi is clear
    while (hi - lo > s.toleranceRad) {
      const double mid = 0.5 * (lo + hi);
      (collides(sign * mid) ? lo : hi) = mid;
    }
    const double withSafety = std::min(hi + s.safetyAngleRad, s.maxTiltRad);
    if (withSafety == hi || !collides(sign * withSafety)) return withSafety;
    fallback = std::min(fallback, hi);
    previous = withSafety;
  }
  return fallback;
}

}  // namespace spira
