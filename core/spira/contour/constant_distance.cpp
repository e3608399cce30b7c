#include "spira/contour/constant_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "spira/base/error.h"
#include "spira/base/segment_distance.h"
#include "spira/base/units.h"

namespace spira {
namespace {

void validate(const TubeSurface& surface, const std::vector<double>& firstLayer, double until,
              const ConstantDistanceSettings& s)
{
  if (!(s.delta > 0.0) || !std::isfinite(s.delta))
    throw InputError("the layer distance must be positive", "give the deposit height, e.g. 2 mm");
  if (s.pointsPerLayer < 8)
    throw InputError("a layer needs at least 8 points, found " + std::to_string(s.pointsPerLayer),
                     "use 360 points per layer");
  if (firstLayer.size() != size_t(s.pointsPerLayer))
    throw InputError("the first layer has " + std::to_string(firstLayer.size()) + " points for " +
                     std::to_string(s.pointsPerLayer) + " per layer");
  if (!surface.at || !(surface.tEnd > until) || !(until > surface.t0))
    throw InputError("the tube's surface must reach past the part's end",
                     "extend the guide curve beyond the nominal end (004_bd0df31205c0c3c0.txt §2.3.2)");
}

}  // namespace

double distanceToClosedLayer(const Vec3& p, const std::vector<Vec3>& layer, int centre, int window)
{
  const int n = int(layer.size());
  double best = std::numeric_limits<double>::infinity();
  const int half = window > 0 && 2 * window + 1 < n ? window : n / 2;
  const int from = window > 0 && 2 * window + 1 < n ? centre - half : 0;
  const int to = window > 0 && 2 * window + 1 < n ? centre + half : n - 1;
  for (int k = from; k <= to; ++k) {
    const int j = ((k % n) + n) % n;
    best = std::min(best, pointSegmentDistance(p, layer[size_t(j)], layer[size_t((j + 1) % n)]));
  }
  return best;
}

double layerAngle(int i, int n)
{
  return 2.0 * kPi * i / n;
}

double turningAngleDeg(const std::vector<Vec3>& layer, int i)
{
  const int n = int(layer.size());
  const Vec3 in = layer[size_t(i)] - layer[size_t((i + n - 1) % n)];
  const Vec3 out = layer[size_t((i + 1) % n)] - layer[size_t(i)];
  if (in.norm() < 1e-12 || out.norm() < 1e-12) return 0.0;
  return radToDeg(std::acos(std::clamp(in.normalized().dot(out.normalized()), -1.0, 1.0)));
}

double maxTurningAngle(const std::vector<Vec3>& closedLayer)
{
  double worst = 0.0;
  for (int i = 0; i < int(closedLayer.size()); ++i) worst = std::max(worst, turningAngleDeg(closedLayer, i));
  return worst;
}

ConstantDistanceLayers constantDistanceLayers(const TubeSurface& surface,
                                              const std::vector<double>& firstLayer, double until,
                                              const ConstantDistanceSettings& s)
{
  validate(surface, firstLayer, until, s);
  const int n = s.pointsPerLayer;
  const int window = s.window > 0 ? s.window : std::max(2, n / 8);
  std::vector<double> v(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) v[size_t(i)] = layerAngle(i, n);

  ConstantDistanceLayers out;
  out.t.push_back(firstLayer);
  out.points.emplace_back();
  for (int i = 0; i < n; ++i) out.points.back().push_back(surface.at(firstLayer[size_t(i)], v[size_t(i)]));

  const auto reached = [&](const std::vector<double>& layer) {
    return *std::min_element(layer.begin(), layer.end()) >= until;
  };
  while (!reached(out.t.back())) {
    const std::vector<double>& belowT = out.t.back();
    const std::vector<Vec3>& below = out.points.back();
    std::vector<double> t(static_cast<size_t>(n));
    std::vector<Vec3> points(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
      const auto gap = [&](double x) {
        return distanceToClosedLayer(surface.at(x, v[size_t(i)]), below, i, window) - s.delta;
      };
      // Bracket: march up from the layer below in steps of about a fifth of delta along the surface,
      // so that a thin tube's opposite wall is never jumped over.
      double lo = belowT[size_t(i)];
      const Vec3 here = surface.at(lo, v[size_t(i)]);
      const double probe = std::min(1e-3, 1e-3 * (surface.tEnd - surface.t0));
      const double speed =
          (surface.at(std::min(surface.tEnd, lo + probe), v[size_t(i)]) - here).norm() / probe;
      const double step = speed > 0.0 ? 0.2 * s.delta / speed : 1e-3 * (surface.tEnd - surface.t0);
      double hi = lo;
      bool found = false;
      while (hi < surface.tEnd) {
        const double next = std::min(surface.tEnd, hi + step);
        if (gap(next) >= 0.0) {
          lo = hi;
          hi = next;
          found = true;
          break;
        }
        hi = next;
      }
      if (!found) return out;  // the surface ends before this point's next layer
      for (int it = 0; it < 200 && hi - lo > 1e-14 * std::max(1.0, std::abs(hi)); ++it) {
        const double mid = 0.5 * (lo + hi);
        const double g = gap(mid);
        if (std::abs(g) <= s.tolerance) {
          lo = hi = mid;
          break;
        }
        (g < 0.0 ? lo : hi) = mid;
      }
      t[size_t(i)] = 0.5 * (lo + hi);
      points[size_t(i)] = surface.at(t[size_t(i)], v[size_t(i)]);
      if (!points[size_t(i)].allFinite()) return out;  // the surface has a hole there (a meshed tube's end)
    }
    if (s.adjustLayer) s.adjustLayer(t, points, below);
    out.t.push_back(std::move(t));
    out.points.push_back(std::move(points));
    if (s.onLayer) s.onLayer(out.t.size());
  }
  out.complete = true;
  return out;
}

}  // namespace spira
