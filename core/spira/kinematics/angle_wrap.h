#pragma once

#include <cmath>

#include "spira/base/units.h"

namespace spira {

// The angle equal to `a` modulo 2 pi in (-pi, pi].
inline double wrapToPi(double a)
{
  double w = std::remainder(a, 2.0 * kPi);
  if (w <= -kPi) w += 2.0 * kPi;
  return w;
}

// The angle equal to `a` modulo 2 pi that is nearest to `reference` (joint unwrapping along a path).
inline double nearestBranch(double a, double reference)
{
  return reference + std::remainder(a - reference, 2.0 * kPi);
}

}  // namespace spira
