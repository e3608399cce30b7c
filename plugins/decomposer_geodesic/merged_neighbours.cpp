#include "merged_neighbours.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

namespace spira::geodesic {

namespace {

double distanceToPolyline(const Vec3& q, const Polyline& line)
{
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k + 1 < line.size(); ++k) {
    const Vec3 d = line[k + 1] - line[k];
    const double dd = d.squaredNorm();
    const double t = dd > 0.0 ? std::clamp((q - line[k]).dot(d) / dd, 0.0, 1.0) : 0.0;
    best = std::min(best, (line[k] + t * d - q).squaredNorm());
  }
  return std::sqrt(best);
}

struct Stretch {
  double length = 0.0;
  size_t points = 0;  // of `a` in the run
  Vec3 from = Vec3::Zero();
  bool longerThan(const Stretch& o) const { return points > 0 && (o.points == 0 || length > o.length); }
};

// The longest run of consecutive inner points of `a` within `gap` of `b`, measured along `a`. The
// ends do not count: neighbours may start on one base point and end on one point of the upper edge.
Stretch longestTogether(const Polyline& a, const Polyline& b, double gap, const std::optional<Vec3>& closure,
                        double closureRadius)
{
  Stretch best, run;
  bool inside = false;
  for (size_t k = 1; k + 1 < a.size(); ++k) {
    const bool nearClosure = closure && (a[k] - *closure).norm() < closureRadius;
    const bool together = !nearClosure && distanceToPolyline(a[k], b) < gap;
    if (together && inside) {
      run.length += (a[k] - a[k - 1]).norm();
      ++run.points;
    } else if (together) {
      run = Stretch{0.0, 1, a[k]};
    }
    inside = together;
    if (inside && run.longerThan(best)) best = run;
  }
  return best;
}

}  // namespace

MergedNeighbours findMergedNeighbours(const std::vector<Polyline>& lines, size_t firstPair, size_t endPair,
                                      double gap, double minStretch, const std::optional<Vec3>& closure,
                                      double closureRadius)
{
  const size_t n = lines.size();
  MergedNeighbours out;
  if (n < 2 || firstPair >= endPair) return out;
  std::vector<Stretch> stretch(endPair - firstPair);
  tbb::parallel_for(firstPair, endPair, [&](size_t i) {
    const Polyline& a = lines[i % n];
    const Polyline& b = lines[(i + 1) % n];
    const Stretch ab = longestTogether(a, b, gap, closure, closureRadius);
    const Stretch ba = longestTogether(b, a, gap, closure, closureRadius);
    stretch[i - firstPair] = ba.longerThan(ab) ? ba : ab;
  });
  for (size_t i = firstPair; i < endPair; ++i) {
    const Stretch& s = stretch[i - firstPair];
    if (s.points == 0 || s.length < minStretch) continue;
    ++out.pairs;
    if (out.pairs == 1 || s.length > out.stretch) {
      out.stretch = s.length;
      out.first = i % n;
      out.from = s.from;
    }
  }
  return out;
}

}  // namespace spira::geodesic
