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
  Vec3 from = Vec3::Zero();
};

// The longest run of consecutive points of `a` within `gap` of `b`, measured along `a`.
Stretch longestTogether(const Polyline& a, const Polyline& b, double gap, const std::optional<Vec3>& closure,
                        double closureRadius)
{
  Stretch best, run;
  bool inside = false;
  for (size_t k = 0; k < a.size(); ++k) {
    const bool nearClosure = closure && (a[k] - *closure).norm() < closureRadius;
    const bool together = !nearClosure && distanceToPolyline(a[k], b) < gap;
    if (together && inside) {
      run.length += (a[k] - a[k - 1]).norm();
    } else if (together) {
      run = Stretch{0.0, a[k]};
    }
    inside = together;
    if (inside && run.length > best.length) best = run;
  }
  return best;
}

}  // namespace

MergedNeighbours findMergedNeighbours(const std::vector<GeneratrixLine>& lines, double gap, double minStretch,
                                      const std::optional<Vec3>& closure, double closureRadius)
{
  const size_t n = lines.size();
  std::vector<Stretch> stretch(n);
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    const Polyline& a = lines[i].points;
    const Polyline& b = lines[(i + 1) % n].points;
    const Stretch ab = longestTogether(a, b, gap, closure, closureRadius);
    const Stretch ba = longestTogether(b, a, gap, closure, closureRadius);
    stretch[i] = ab.length >= ba.length ? ab : ba;
  });
  MergedNeighbours out;
  for (size_t i = 0; i < n; ++i) {
    if (!(stretch[i].length > minStretch)) continue;
    ++out.pairs;
    if (stretch[i].length > out.stretch) {
      out.stretch = stretch[i].length;
      out.first = i;
      out.from = stretch[i].from;
    }
  }
  return out;
}

}  // namespace spira::geodesic
