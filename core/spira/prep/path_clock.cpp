#include "spira/prep/path_clock.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "spira/base/error.h"

namespace spira {

namespace {

// Time to cover length len while the speed goes linearly from v0 to v1.
double intervalTime(double len, double v0, double v1)
{
  const double r = v1 / v0;
  if (std::abs(r - 1.0) < 1e-6) return 2.0 * len / (v0 + v1);
  return len * std::log(r) / (v1 - v0);
}

}  // namespace

PathClock::PathClock(const Trajectory& path)
{
  const size_t n = path.size();
  time_.assign(n, 0.0);
  arc_.assign(n, 0.0);
  speed_.resize(n);
  for (size_t k = 0; k < n; ++k) {
    speed_[k] = path.points[k].travelSpeed;
    if (!(speed_[k] > 0.0) || !std::isfinite(speed_[k])) {
      throw InputError("travel speed at trajectory point " + std::to_string(k) + " is not positive",
                       "give every point of the path a positive travel speed before leading its channels");
    }
    if (k == 0) continue;
    const double len = (path.points[k].position - path.points[k - 1].position).norm();
    arc_[k] = arc_[k - 1] + len;
    time_[k] = time_[k - 1] + intervalTime(len, speed_[k - 1], speed_[k]);
  }
}

double PathClock::arcAtTime(double t) const
{
  if (time_.empty() || t <= 0.0) return 0.0;
  if (t >= time_.back()) return arc_.back();
  const size_t k = static_cast<size_t>(std::upper_bound(time_.begin(), time_.end(), t) - time_.begin()) - 1;
  const double len = arc_[k + 1] - arc_[k];
  const double tau = t - time_[k];
  // v(s) = v0 + g s  =>  t(s) = ln(1 + g s / v0) / g  =>  s(t) = v0 (exp(g t) - 1) / g.
  const double g = len > 0.0 ? (speed_[k + 1] - speed_[k]) / len : 0.0;
  const double s = std::abs(g * tau) < 1e-12 ? speed_[k] * tau : speed_[k] * std::expm1(g * tau) / g;
  return arc_[k] + std::clamp(s, 0.0, len);
}

}  // namespace spira
