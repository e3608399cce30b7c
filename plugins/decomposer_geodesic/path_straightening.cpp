#include "path_straightening.h"

#include <cmath>
#include <optional>
#include <vector>

#include "spira/base/golden_section.h"
#include "strip_unfolding.h"

namespace spira::geodesic {

namespace {

double polylineLength(const std::vector<PathPoint>& points)
{
  double length = 0.0;
  for (size_t k = 1; k < points.size(); ++k) length += (points[k].position - points[k - 1].position).norm();
  return length;
}

bool onEdge(const PathPoint& p)
{
  return p.vertices[0] >= 0 && p.vertices[1] >= 0 && p.vertices[2] < 0;
}

// The t in [0, 1] minimising |a - x(t)| + |x(t) - b|, x(t) = (1 - t) p + t q: golden section on a
// convex function.
double bestCrossing(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q)
{
  const auto f = [&](double t) {
    const Vec3 x = (1.0 - t) * p + t * q;
    return (a - x).norm() + (x - b).norm();
  };
  const double t = goldenSectionMinimum(f, 0.0, 1.0, {80, 1e-14, GoldenTie::KeepLower});
  // The ends themselves: golden section never evaluates them.
  if (f(0.0) <= f(t)) return f(1.0) < f(0.0) ? 1.0 : 0.0;
  return f(1.0) < f(t) ? 1.0 : t;
}

}  // namespace

double straightenPath(ExactPath& path, double exactLength, const StripMesh& mesh, int maxSweeps)
{
  std::vector<PathPoint>& pts = path.points;
  double length = polylineLength(pts);
  if (pts.size() < 3 || !(exactLength > 0.0)) return length;
  if (length > exactLength * (1.0 + 1e-9)) {
    // Between two points off the edges (the ends, vertices the path bends at) the geodesic is the
    // straight line of the unfolded strip: put the crossings there at once. Kept only if shorter.
    std::vector<PathPoint> unfolded{pts.front()};
    size_t anchor = 0;
    for (size_t k = 1; k < pts.size(); ++k) {
      if (k + 1 != pts.size() && onEdge(pts[k])) continue;
      const std::vector<PathPoint> run(pts.begin() + long(anchor), pts.begin() + long(k) + 1);
      const std::optional<std::vector<PathPoint>> straight = straightRun(run, mesh);
      const std::vector<PathPoint>& use = straight ? *straight : run;
      unfolded.insert(unfolded.end(), use.begin() + 1, use.end());
      anchor = k;
    }
    const double shorter = polylineLength(unfolded);
    if (shorter < length) {
      pts = std::move(unfolded);
      length = shorter;
    }
  }
  for (int sweep = 0; sweep < maxSweeps && length > exactLength * (1.0 + 1e-9); ++sweep) {
    for (size_t k = 1; k + 1 < pts.size(); ++k) {
      PathPoint& p = pts[k];
      if (!onEdge(p)) continue;
      const Vec3 e0 = mesh.position(p.vertices[0]), e1 = mesh.position(p.vertices[1]);
      const double t = bestCrossing(pts[k - 1].position, pts[k + 1].position, e0, e1);
      p.weights = Vec3(1.0 - t, t, 0.0);
      p.position = (1.0 - t) * e0 + t * e1;
    }
    const double next = polylineLength(pts);
    if (next > length - 1e-12 * length) {
      length = next;
      break;  // no progress left
    }
    length = next;
  }
  return length;
}

}  // namespace spira::geodesic
