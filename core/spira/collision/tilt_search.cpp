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
  while (previous < s.maxTiltRad) {
    const double m = std::min(previous + s.searchStepRad, s.maxTiltRad);
    if (checker.collides(i, sign * m)) {
      previous = m;
      continue;
    }
    double lo = previous, hi = m;  // lo collides, hi is clear
    while (hi - lo > s.toleranceRad) {
      const double mid = 0.5 * (lo + hi);
      (checker.collides(i, sign * mid) ? lo : hi) = mid;
    }
    const double withSafety = std::min(hi + s.safetyAngleRad, s.maxTiltRad);
    if (withSafety == hi || !checker.collides(i, sign * withSafety)) return withSafety;
    fallback = std::min(fallback, hi);
    previous = withSafety;
  }
  return fallback;
}

}  // namespace spira
