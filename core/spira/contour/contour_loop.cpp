#include "spira/contour/contour_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "spira/base/error.h"

namespace spira {

double polylineLength(const std::vector<Vec3>& points, bool closed)
{
  const size_t m = points.size();
  if (m < 2) return 0.0;
  double len = 0.0;
  for (size_t i = 0; i + 1 < m; ++i) len += (points[i + 1] - points[i]).norm();
  if (closed) len += (points[0] - points[m - 1]).norm();
  return len;
}

Vec3 vectorArea(const std::vector<Vec3>& loop)
{
  // Relative to the first point, so that far-from-origin loops lose no precision.
  Vec3 a = Vec3::Zero();
  const size_t m = loop.size();
  for (size_t i = 1; i + 1 < m; ++i) a += (loop[i] - loop[0]).cross(loop[i + 1] - loop[0]);
  return 0.5 * a;
}

bool isCounterClockwise(const IsoContour& loop, const Vec3& axis)
{
  return vectorArea(loop.positions()).dot(axis) > 0;
}

bool orientCounterClockwise(IsoContour& loop, const Vec3& axis)
{
  if (isCounterClockwise(loop, axis)) return false;
  loop.reverse();
  return true;
}

std::vector<Vec3> ResampledLoop::positions() const
{
  std::vector<Vec3> out;
  out.reserve(points.size());
  for (const auto& p : points) out.push_back(p.position);
  return out;
}

namespace {

void requireLoop(const IsoContour& loop)
{
  if (!loop.closed || loop.points.size() < 3)
    throw InputError("the iso-contour at field value " + std::to_string(loop.level) +
                         " is not a closed loop, so it cannot be resampled around the part",
                     "the field must be constant along each free edge of the part");
}

// Cumulative arc length at each point, plus the total at the end.
std::vector<double> cumulativeLength(const IsoContour& loop)
{
  const size_t m = loop.points.size();
  std::vector<double> cum(m + 1, 0.0);
  for (size_t i = 0; i < m; ++i)
    cum[i + 1] = cum[i] + (loop.points[(i + 1) % m].position - loop.points[i].position).norm();
  return cum;
}

}  // namespace

double nearestArcParameter(const IsoContour& loop, const Vec3& q)
{
  requireLoop(loop);
  const std::vector<double> cum = cumulativeLength(loop);
  const size_t m = loop.points.size();
  double best = std::numeric_limits<double>::infinity(), bestArc = 0.0;
  for (size_t i = 0; i < m; ++i) {
    const Vec3& a = loop.points[i].position;
    const Vec3 ab = loop.points[(i + 1) % m].position - a;
    const double len2 = ab.squaredNorm();
    const double u = len2 > 0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const double d2 = (a + u * ab - q).squaredNorm();
    if (d2 < best) {
      best = d2;
      bestArc = cum[i] + u * (cum[i + 1] - cum[i]);
    }
  }
  return bestArc >= cum[m] ? 0.0 : bestArc;
}

ResampledLoop resampleLoop(const TriangleMesh& mesh, const IsoContour& loop, size_t n, double startArc)
{
  requireLoop(loop);
  if (n < 3)
    throw InputError("a loop needs at least 3 points, not " + std::to_string(n), "ask for more points");
  const std::vector<double> cum = cumulativeLength(loop);
  const size_t m = loop.points.size();
  const double total = cum[m];
  ResampledLoop out;
  out.level = loop.level;
  out.length = total;
  out.points.resize(n);
  startArc = std::fmod(startArc, total);
  if (startArc < 0) startArc += total;
  for (size_t k = 0; k < n; ++k) {
    double s = startArc + total * static_cast<double>(k) / static_cast<double>(n);
    if (s >= total) s -= total;
    // Segment i with cum[i] <= s < cum[i+1].
    size_t i = static_cast<size_t>(std::upper_bound(cum.begin(), cum.end(), s) - cum.begin());
    i = std::min(i == 0 ? 0 : i - 1, m - 1);
    const double segLen = cum[i + 1] - cum[i];
    const double u = segLen > 0 ? std::clamp((s - cum[i]) / segLen, 0.0, 1.0) : 0.0;
    const size_t j = (i + 1) % m;
    const int face = loop.segmentFaces[i];
    SurfacePoint& p = out.points[k];
    p.position = (1.0 - u) * loop.points[i].position + u * loop.points[j].position;
    p.face = face;
    p.bary = (1.0 - u) * loop.barycentricIn(mesh, i, face) + u * loop.barycentricIn(mesh, j, face);
  }
  return out;
}

ResampledLoop resampleLoopContinuing(const TriangleMesh& mesh, const IsoContour& loop, size_t n,
                                     const Vec3& previousStart)
{
  return resampleLoop(mesh, loop, n, nearestArcParameter(loop, previousStart));
}

size_t nearestIndex(const std::vector<SurfacePoint>& points, const Vec3& q)
{
  size_t best = 0;
  double bestD2 = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < points.size(); ++i) {
    const double d2 = (points[i].position - q).squaredNorm();
    if (d2 < bestD2) {
      bestD2 = d2;
      best = i;
    }
  }
  return best;
}

}  // namespace spira
