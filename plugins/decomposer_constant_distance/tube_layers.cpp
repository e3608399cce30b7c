#include "tube_layers.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/contour/guided_tube.h"
#include "spira/contour/meshed_tube.h"

namespace spira {
namespace {

std::string mm(double x, int digits = 1)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}

std::string pointText(const Vec3& p)
{
  return "(" + mm(p.x()) + ", " + mm(p.y()) + ", " + mm(p.z()) + ")";
}

// Every ray across the guide inside the part meets the wall, and the tube is wider than a layer is high.
// Checked between the base edge and the upper edge, where the wall goes all round (a feature's base on a
// pipe is slanted across the guide).
double checkGuideInside(const TubeSurface& tube, const std::function<Vec3(double)>& guide, double from,
                        double to, double delta)
{
  double narrowest = std::numeric_limits<double>::infinity();
  constexpr int kSamples = 64, kAround = 8;
  for (int k = 0; k <= kSamples; ++k) {
    const double t = from + (to - from) * (0.02 + 0.96 * k / kSamples);
    double sum = 0.0;
    for (int j = 0; j < kAround; ++j) {
      const Vec3 p = tube.at(t, layerAngle(j, kAround));
      if (!p.allFinite())
        throw InputError(
            "the guide curve leaves the part near " + pointText(guide(t)) + ", " + mm(t) +
                " mm along it: no wall around it there",
            "give the tube's centre line with --guide (base end first), or leave --guide empty to "
            "take it from the part");
      sum += (p - guide(t)).norm();
    }
    narrowest = std::min(narrowest, sum / kAround);
  }
  if (!(delta < narrowest))
    throw InputError(
        "the layer distance " + mm(delta, 2) + " mm is not smaller than the tube's radius (" +
            mm(narrowest, 2) + " mm where it is narrowest)",
        "lower --h below " + mm(narrowest, 1) + " mm: a layer that high would reach the opposite wall");
  return narrowest;
}

// The part's surface up to its upper edge, then straight on along the guide's tangent there, so that
// layers can be laid past the end and cut by it.
TubeSurface continuedPastTop(const TubeSurface& tube, const std::function<Vec3(double)>& guide,
                             const std::vector<double>& top, double tEnd)
{
  const int n = int(top.size());
  std::vector<Vec3> edge(top.size()), along(top.size());
  for (int i = 0; i < n; ++i) {
    edge[size_t(i)] = tube.at(top[size_t(i)], layerAngle(i, n));
    constexpr double e = 1e-3;
    along[size_t(i)] = (guide(top[size_t(i)] + e) - guide(top[size_t(i)] - e)).normalized();
  }
  TubeSurface out;
  out.t0 = tube.t0;
  out.tEnd = tEnd;
  const auto index = [n](double v) { return ((int(std::lround(v * n / (2.0 * kPi))) % n) + n) % n; };
  out.at = [tube, top, edge, along, index](double t, double v) {
    const int i = index(v);
    if (t <= top[size_t(i)]) return tube.at(t, v);
    return Vec3(edge[size_t(i)] + (t - top[size_t(i)]) * along[size_t(i)]);
  };
  if (tube.normal)
    out.normal = [tube, top, index](double t, double v) {
      return tube.normal(std::min(t, top[size_t(index(v))]), v);
    };
  return out;
}

struct Range {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  void add(double x)
  {
    min = std::min(min, x);
    max = std::max(max, x);
  }
};

// The last layers re-laid from layer `from` to the upper edge in `count` layers, equal steps in t.
std::vector<std::vector<double>> band(const TubeLayers& L, size_t from, int count)
{
  std::vector<std::vector<double>> t;
  for (int j = 1; j <= count; ++j) {
    std::vector<double> layer(L.top.size());
    for (size_t i = 0; i < layer.size(); ++i)
      layer[i] = L.t[from][i] + (L.top[i] - L.t[from][i]) * double(j) / count;
    t.push_back(std::move(layer));
  }
  return t;
}

std::vector<Vec3> pointsAt(const TubeSurface& surface, const std::vector<double>& t)
{
  const int n = int(t.size());
  std::vector<Vec3> p(t.size());
  for (int i = 0; i < n; ++i) p[size_t(i)] = surface.at(t[size_t(i)], layerAngle(i, n));
  return p;
}

// The deposit heights a band would lay: every point's distance to the layer under it.
Range bandHeights(const TubeLayers& L, size_t from, const std::vector<std::vector<double>>& t,
                  std::vector<std::vector<Vec3>>* points)
{
  Range r;
  std::vector<Vec3> below = L.points[from];
  for (const std::vector<double>& layer : t) {
    std::vector<Vec3> p = pointsAt(L.surface, layer);
    for (double d : layerDistances(p, below)) r.add(d);
    below = p;
    if (points) points->push_back(std::move(p));
  }
  return r;
}

void modulateEnd(TubeLayers& L, const TubeLayerSettings& s)
{
  const size_t n = L.top.size();
  size_t lastInside = 0;
  for (size_t k = 0; k < L.t.size(); ++k) {
    bool inside = true;
    for (size_t i = 0; i < n && inside; ++i) inside = L.t[k][i] <= L.top[i];
    if (inside) lastInside = k;
  }
  double gapSpread = 0.0;
  {
    Range gap;
    for (size_t i = 0; i < n; ++i)
      gap.add((L.surface.at(L.top[i], layerAngle(int(i), int(n))) - L.points[lastInside][i]).norm());
    gapSpread = gap.max - gap.min;
  }
  const double low = s.hMin - s.tolerance, high = s.hMax + s.tolerance;
  struct Choice {
    size_t from = 0;
    int count = 0;
    double excess = std::numeric_limits<double>::infinity();  // mm outside the window at worst
  } best;
  for (size_t from = lastInside + 1; from-- > 0;) {
    Range gap;
    for (size_t i = 0; i < n; ++i)
      gap.add((L.surface.at(L.top[i], layerAngle(int(i), int(n))) - L.points[from][i]).norm());
    if (gap.max < 1e-9) continue;
    const int fewest = std::max(1, int(std::ceil(gap.max / s.hMax - 1e-9)));
    const int most = std::max(fewest, int(std::floor(gap.min / s.hMin + 1e-9)));
    std::vector<int> counts;
    for (int c = fewest; c <= most && c <= fewest + 4; ++c) counts.push_back(c);
    // Nearest the nominal height first.
    const double mean = 0.5 * (gap.min + gap.max);
    std::sort(counts.begin(), counts.end(),
              [&](int a, int b) { return std::abs(mean / a - s.delta) < std::abs(mean / b - s.delta); });
    for (int c : counts) {
      const Range h = bandHeights(L, from, band(L, from, c), nullptr);
      const double excess = std::max({0.0, low - h.min, h.max - high});
      if (excess < best.excess) best = {from, c, excess};
      if (excess == 0.0) break;
    }
    if (best.excess == 0.0) break;
  }
  if (best.count == 0) return;
  std::vector<std::vector<Vec3>> points;
  std::vector<std::vector<double>> t = band(L, best.from, best.count);
  const Range h = bandHeights(L, best.from, t, &points);
  L.t.resize(best.from + 1);
  L.points.resize(best.from + 1);
  L.constantLayers = int(best.from);
  for (size_t j = 0; j < t.size(); ++j) {
    L.t.push_back(std::move(t[j]));
    L.points.push_back(std::move(points[j]));
  }
  if (best.excess > 0.0)
    throw InputError(
        "the layers cannot end on the upper edge inside the process window: it lies " + mm(gapSpread, 1) +
            " mm further up the tube on one side than on the other, and the "
            "closest re-laid ending (the last " +
            std::to_string(best.count) + " layers) lays " + mm(h.min, 2) + " .. " + mm(h.max, 2) +
            " mm beads for a window of " + mm(s.hMin, 2) + " .. " + mm(s.hMax, 2) + " mm",
        "use --end truncate (layers laid past the edge and cut by it), or widen the window to " +
            mm(std::min(h.min, s.hMin), 2) + " .. " + mm(std::max(h.max, s.hMax), 2) + " mm");
}

void truncateEnd(TubeLayers& L)
{
  const size_t n = L.top.size();
  L.constantLayers = int(L.t.size()) - 1;
  for (size_t k = 0; k < L.t.size(); ++k)
    for (size_t i = 0; i < n; ++i) L.kept[k][i] = L.t[k][i] <= L.top[i] + 1e-9;
  // Layers wholly past the end lay nothing.
  while (L.t.size() > 1 &&
         std::none_of(L.kept.back().begin(), L.kept.back().end(), [](char c) { return c; })) {
    L.t.pop_back();
    L.points.pop_back();
    L.kept.pop_back();
  }
}

// Relaxes the layer's t towards its neighbours' around every point turning more than `maxDeg`, each move
// cut short where the point's distance to the layer below would leave [low, high]. Returns the points moved.
int smoothKinks(const TubeSurface& surface, std::vector<double>& t, std::vector<Vec3>& p,
                const std::vector<Vec3>& below, double maxDeg, double low, double high)
{
  const int n = int(t.size());
  const int window = std::max(2, n / 8);
  constexpr int kReach = 3, kPasses = 60;
  std::vector<char> moved(t.size(), 0);
  for (int pass = 0; pass < kPasses; ++pass) {
    std::vector<char> near(t.size(), 0);
    bool any = false;
    for (int i = 0; i < n; ++i)
      if (turningAngleDeg(p, i) > maxDeg) {
        any = true;
        for (int d = -kReach; d <= kReach; ++d) near[size_t(((i + d) % n + n) % n)] = 1;
      }
    if (!any) break;
    bool changed = false;
    for (int i = 0; i < n; ++i) {
      if (!near[size_t(i)]) continue;
      const double v = 2.0 * kPi * i / n;
      const double target = 0.5 * (t[size_t((i + n - 1) % n)] + t[size_t((i + 1) % n)]);
      const auto fits = [&](double x) {
        const Vec3 q = surface.at(x, v);
        const double d = q.allFinite() ? distanceToClosedLayer(q, below, i, window) : -1.0;
        return d >= low && d <= high;
      };
      double to = t[size_t(i)] + 0.5 * (target - t[size_t(i)]);
      if (!fits(to)) {
        double ok = t[size_t(i)], bad = to;
        if (!fits(ok)) continue;
        for (int it = 0; it < 30; ++it) {
          const double mid = 0.5 * (ok + bad);
          (fits(mid) ? ok : bad) = mid;
        }
        to = ok;
      }
      if (std::abs(to - t[size_t(i)]) < 1e-9) continue;
      t[size_t(i)] = to;
      p[size_t(i)] = surface.at(to, v);
      moved[size_t(i)] = 1;
      changed = true;
    }
    if (!changed) break;
  }
  return int(std::count(moved.begin(), moved.end(), 1));
}

// A layer point that could not be put delta above the layer below lies where the surface jumps along its
// generatrix: a ledge, lip or fold the guide's rays cross, which no layer at a constant distance follows.
// Smoothed kinks (settings.smoothKinkDeg) are off the distance on purpose, inside the window.
void refuseSteps(const ConstantDistanceLayers& layers, const TubeLayerSettings& s)
{
  const double delta = s.delta;
  double worst = 0.0;
  Vec3 at = Vec3::Zero();
  for (size_t k = 1; k < layers.points.size(); ++k) {
    const std::vector<double> d = layerDistances(layers.points[k], layers.points[k - 1]);
    for (size_t i = 0; i < d.size(); ++i) {
      if (s.smoothKinkDeg > 0.0 && d[i] >= s.hMin && d[i] <= s.hMax) continue;
      if (std::abs(d[i] - delta) > worst) worst = std::abs(d[i] - delta), at = layers.points[k][i];
    }
  }
  if (worst <= 0.01 * delta) return;
  throw InputError(
      "the wall steps across the tube near " + pointText(at) +
          " (a ledge, lip or fold): a layer there cannot lie " + mm(delta, 2) +
          " mm from the one below (it would lie " + mm(worst, 2) + " mm off)",
      "plan the part with --strategy isovalue, which follows the surface itself, or smooth the step "
      "in the CAD model");
}

}  // namespace

std::vector<double> layerDistances(const std::vector<Vec3>& layer, const std::vector<Vec3>& below,
                                   const std::vector<char>& use)
{
  const int n = int(layer.size());
  const int window = std::max(2, n / 8);
  std::vector<double> d;
  d.reserve(layer.size());
  for (int i = 0; i < n; ++i)
    if (use.empty() || use[size_t(i)]) d.push_back(distanceToClosedLayer(layer[size_t(i)], below, i, window));
  return d;
}

TubeLayers layTubeLayers(const TriangleMesh& mesh, const Polyline& centreLine, double reach,
                         const TubeLayerSettings& s, Progress& progress)
{
  TubeLayers L;
  L.guide = polylineGuide(centreLine);
  double length = 0.0;
  for (size_t k = 1; k < centreLine.size(); ++k) length += (centreLine[k] - centreLine[k - 1]).norm();
  // Past both ends by the reach, so the base edge and the upper edge are met whatever their slant.
  const double ext = reach;
  progress.report(0.0, "tube surface");
  const TubeSurface tube = meshedTube(mesh, L.guide, -ext, length + ext, reach);
  std::vector<double> base;
  try {
    base = baseLayer(tube, s.points, -ext, 0.5 * length);
    L.top = topLayer(tube, s.points, 0.5 * length, length + ext);
  } catch (const InputError& e) {
    throw InputError(
        "the guide curve leaves the part: " + std::string(e.what()),
        "give the tube's centre line with --guide (base end first), or leave --guide empty to take it "
        "from the part");
  }
  const double topMax = *std::max_element(L.top.begin(), L.top.end());
  const double topMin = *std::min_element(L.top.begin(), L.top.end());
  const double baseMax = *std::max_element(base.begin(), base.end());
  if (!(topMin > baseMax + s.delta))
    throw InputError(
        "the tube is shorter than one layer along its guide (" + mm(topMin - baseMax, 2) + " mm)",
        "plan a part at least one deposit high");
  L.radiusMin = checkGuideInside(tube, L.guide, baseMax, topMin, s.delta);
  progress.checkCancel();
  L.surface = continuedPastTop(tube, L.guide, L.top, topMax + 2.0 * (topMax - tube.t0) + 10.0 * s.delta);

  ConstantDistanceSettings cd;
  cd.delta = s.delta;
  cd.pointsPerLayer = s.points;
  const double expected = (topMax - tube.t0) / s.delta + 1.0;
  cd.onLayer = [&](size_t layers) {
    progress.report(std::min(0.95, 0.05 + 0.9 * double(layers) / expected), "constant-distance layers");
    progress.checkCancel();
  };
  // The deposit check measures a smoothed point along its build direction, a few hundredths off the
  // distance the smoothing keeps: it aims that much inside the window.
  const double margin = 0.05 * (s.hMax - s.hMin);
  if (s.smoothKinkDeg > 0.0)
    cd.adjustLayer = [&](std::vector<double>& t, std::vector<Vec3>& points, const std::vector<Vec3>& below) {
      L.smoothedPoints +=
          smoothKinks(L.surface, t, points, below, s.smoothKinkDeg, s.hMin + margin, s.hMax - margin);
    };
  progress.report(0.05, "constant-distance layers");
  ConstantDistanceLayers layers = constantDistanceLayers(L.surface, base, topMax + 1e-9, cd);
  if (!layers.complete) {
    const std::vector<Vec3>& last = layers.points.back();
    Vec3 centre = Vec3::Zero();
    for (const Vec3& p : last) centre += p / double(last.size());
    throw InputError("the constant-distance layers stop after " + std::to_string(layers.t.size() - 1) +
                         " layers, around " + pointText(centre) +
                         ": the next layer does not find the wall all around there (the wall parts into "
                         "branches, has a gap, or the guide leaves the tube)",
                     "plan a branching part with --strategy isovalue, close the gap in the mesh, or give the "
                     "tube's centre line with --guide");
  }
  refuseSteps(layers, s);
  L.t = std::move(layers.t);
  L.points = std::move(layers.points);
  L.kept.assign(L.t.size(), std::vector<char>(size_t(s.points), 1));
  if (s.end == TubeEnd::Truncate) {
    truncateEnd(L);
  } else {
    modulateEnd(L, s);
    L.kept.assign(L.t.size(), std::vector<char>(size_t(s.points), 1));
  }
  progress.report(1.0, "constant-distance layers");
  return L;
}

}  // namespace spira
