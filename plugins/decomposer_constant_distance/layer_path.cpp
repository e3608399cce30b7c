#include "layer_path.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/path/seam_placement.h"
#include "spira/path/spiral_builder.h"
#include "spira/path/spiral_frames.h"
#include "spira/path/startup_profile.h"

namespace spira {
namespace {

constexpr double kGoldenFraction = 0.3819660112501051;  // 1 - 1/phi: 137.5 deg of a turn

// The outward surface normal at (t, v_i): the surface's own where it has one (a mesh's, smooth across
// faces), else across the generatrices by the neighbouring ones and along them by a short step in t.
Vec3 normalAt(const TubeLayers& L, double t, int i)
{
  const int n = int(L.top.size());
  if (L.surface.normal) {
    // Averaged over half a millimetre around the point: a sliver face of the mesh (a crease between two
    // patches of a CAD export) turns the normal it alone gives, and with it the torch, by up to 90 deg.
    constexpr double e = 0.5;
    const double v = layerAngle(i, n), dv = e / std::max(L.radiusMin, 1.0);
    Vec3 sum = Vec3::Zero();
    for (const auto& [dt, dw] : {std::pair{0.0, 0.0}, {e, 0.0}, {-e, 0.0}, {0.0, dv}, {0.0, -dv}})
      sum += L.surface.normal(t + dt, v + dw);
    if (sum.norm() > 1e-9) return sum.normalized();
  }
  constexpr double e = 0.05;
  const Vec3 across =
      L.surface.at(t, layerAngle((i + 1) % n, n)) - L.surface.at(t, layerAngle((i + n - 1) % n, n));
  const Vec3 along = L.surface.at(t + e, layerAngle(i, n)) - L.surface.at(t - e, layerAngle(i, n));
  Vec3 normal = across.cross(along);
  if (!(normal.norm() > 1e-12)) return (L.surface.at(t, layerAngle(i, n)) - L.guide(t)).normalized();
  normal.normalize();
  if (normal.dot(L.surface.at(t, layerAngle(i, n)) - L.guide(t)) < 0.0) normal = -normal;
  return normal;
}

struct Builder {
  Trajectory path;
  std::vector<Vec3> steps;
  int subPath = -1;
  bool open = false;  // the current sub-path takes the next point

  void add(const TubeLayers& L, double t, int i, int revolution, const Vec3& position, const Vec3& below)
  {
    if (!open) ++subPath;
    open = true;
    TrajectoryPoint p;
    p.position = position;
    p.normal = normalAt(L, t, i);
    p.revolution = revolution;
    p.generatrix = i;
    p.path = subPath;
    path.points.push_back(p);
    steps.push_back(position - below);
  }
  void close() { open = false; }
};

// The first point of each piece of a layer on the part, in the order the layer is laid from `start`: a
// whole layer is one piece from `start` round to it; a cut one starts a piece after each gap.
std::vector<int> pieceStarts(const std::vector<char>& kept, int start)
{
  const int n = int(kept.size());
  if (std::all_of(kept.begin(), kept.end(), [](char c) { return c; })) return {start};
  std::vector<int> starts;
  for (int j = 0; j < n; ++j) {
    const int i = (start + j) % n;
    if (kept[size_t(i)] && !kept[size_t((i + n - 1) % n)]) starts.push_back(i);
  }
  return starts;
}

// The point where a closed layer turns most.
int sharpestTurn(const std::vector<Vec3>& layer)
{
  int best = 0;
  for (int i = 1; i < int(layer.size()); ++i)
    if (turningAngleDeg(layer, i) > turningAngleDeg(layer, best)) best = i;
  return best;
}

int layerStart(const LayerPathSettings& s, const std::vector<Vec3>& points, int layer, int n)
{
  switch (s.stagger) {
    case Stagger::None:
      return 0;
    case Stagger::Kink:
      return sharpestTurn(points);
    case Stagger::Constant:
      return int(std::lround(layer * s.staggerAngle / (2.0 * kPi) * n)) % n;
    case Stagger::Golden:
      break;
  }
  const double turn = layer * kGoldenFraction;
  return int(std::lround((turn - std::floor(turn)) * n)) % n;
}

void layLayers(const TubeLayers& L, const LayerPathSettings& s, Builder& b, size_t& firstRing)
{
  const int n = int(L.top.size());
  for (size_t k = 1; k < L.t.size(); ++k) {
    const std::vector<char>& kept = L.kept[k];
    const bool whole = std::all_of(kept.begin(), kept.end(), [](char c) { return c; });
    const int start = layerStart(s, L.points[k], int(k), n);
    for (int first : pieceStarts(kept, start)) {
      // A whole layer closes on its start; a piece runs to its last point on the part.
      const int count = whole ? n + 1 : [&] {
        int c = 0;
        while (c < n && kept[size_t((first + c) % n)]) ++c;
        return c;
      }();
      if (count < 2) continue;
      for (int j = 0; j < count; ++j) {
        const int i = (first + j) % n;
        b.add(L, L.t[k][size_t(i)], i, int(k) - 1, L.points[k][size_t(i)], L.points[k - 1][size_t(i)]);
      }
      b.close();
    }
    if (k == 1) firstRing = b.path.size();
  }
}

// The first layer's height at each point as a deposit on the substrate is measured: along the build
// direction (the wall's direction across the layer) down to the plane, or to the substrate mesh.
std::vector<double> firstLayerHeights(const TubeLayers& L, const SubstrateSurface* substrate, double h)
{
  const int n = int(L.top.size());
  std::vector<double> d = layerDistances(L.points[1], L.points[0]);
  for (int i = 0; i < n; ++i) {
    const Vec3 along = L.points[1][size_t((i + 1) % n)] - L.points[1][size_t((i + n - 1) % n)];
    Vec3 build = normalAt(L, L.t[1][size_t(i)], i).cross(along).normalized();
    const Vec3 rise = L.points[1][size_t(i)] - L.points[0][size_t(i)];
    if (build.dot(rise) < 0.0) build = -build;
    const double depth = substrate ? substrate->depthBelow(L.points[1][size_t(i)], build, 3.0 * h, 10.0 * h)
                                   : (build.z() >= 0.1 ? rise.z() / build.z() : d[size_t(i)]);
    if (std::isfinite(depth) && depth > 0.0) d[size_t(i)] = depth;
  }
  return d;
}

// The t at generatrix i that lies `rise` above layer `k` on the way to layer k + 1 (`step` above it).
// Above the first layer the point is found at that distance from layer k, as the layers themselves are
// (so a revolution between two layers is an offset of the one under it, kinks and all); on the first,
// whose step is measured down to the substrate plane, by proportion along the generatrix.
double levelToT(const TubeLayers& L, size_t k, int i, double rise, double step)
{
  const double lo = L.t[k][size_t(i)], hi = L.t[k + 1][size_t(i)];
  const double f = std::clamp(rise / step, 0.0, 1.0);
  if (k == 0 || f == 0.0 || f == 1.0) return lo + f * (hi - lo);
  const int n = int(L.top.size());
  const int window = std::max(2, n / 8);
  const double v = layerAngle(i, n);
  double a = lo, b = hi;
  for (int it = 0; it < 48 && b - a > 1e-9 * std::max(1.0, std::abs(b)); ++it) {
    const double mid = 0.5 * (a + b);
    (distanceToClosedLayer(L.surface.at(mid, v), L.points[k], i, window) < rise ? a : b) = mid;
  }
  return 0.5 * (a + b);
}

// Level space: generatrix i climbs, layer by layer, the deposit measured at i.
std::vector<std::vector<double>> levels(const TubeLayers& L, const LayerPathSettings& s)
{
  const size_t n = L.top.size();
  std::vector<std::vector<double>> z(n, std::vector<double>{0.0});
  for (size_t k = 1; k < L.t.size(); ++k) {
    const std::vector<double> d =
        k == 1 ? firstLayerHeights(L, s.substrate, s.window.h) : layerDistances(L.points[k], L.points[k - 1]);
    for (size_t i = 0; i < n; ++i) z[i].push_back(z[i].back() + std::max(d[i], 1e-9));
  }
  return z;
}

// Each point's deposit: how far under it, along its build direction, the layer or revolution before it
// was laid where it crosses the plane across the travel through the point (the seam's climb into this
// revolution included, at its foot), as the deposit check measures it; on constant-distance layers that
// is the source's delta (Eq. 2.20). The first ring rests on the substrate plane and keeps the height
// computeDepositHeights gave it.
void measureOnLayerBelow(Trajectory& path, size_t firstRing, int pointsPerLayer, double reach)
{
  auto& pts = path.points;
  std::map<int, std::vector<std::pair<size_t, size_t>>> segments;  // per revolution
  for (size_t q = 1; q < pts.size(); ++q)
    if (pts[q].path == pts[q - 1].path) segments[pts[q - 1].revolution].emplace_back(q - 1, q);
  const int window = std::max(2, pointsPerLayer / 8);
  for (size_t q = firstRing; q < pts.size(); ++q) {
    const auto below = segments.find(pts[q].revolution - 1);
    if (below == segments.end()) continue;
    const Vec3 &p = pts[q].position, &up = pts[q].build, &along = pts[q].tangent;
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [a, b] : below->second) {
      if (a == q || b == q) continue;
      const int gap = std::abs(pts[a].generatrix - pts[q].generatrix);
      if (std::min(gap, pointsPerLayer - gap) > window) continue;
      const double da = along.dot(pts[a].position - p), db = along.dot(pts[b].position - p);
      if ((da > 0.0 && db > 0.0) || (da < 0.0 && db < 0.0) || da == db) continue;
      const bool seam = pts[a].revolution != pts[b].revolution;
      const Vec3 x = seam ? pts[a].position
                          : Vec3(pts[a].position + da / (da - db) * (pts[b].position - pts[a].position));
      const Vec3 down = p - x;
      const double depth = down.dot(up);
      if (depth > 0.0 && (down - depth * up).norm() <= reach) best = std::min(best, depth);
    }
    if (std::isfinite(best)) pts[q].height = best;
  }
}

SpiralReport laySpiral(const TubeLayers& L, const LayerPathSettings& s, Builder& b, size_t& firstRing,
                       Progress& progress)
{
  const int n = int(L.top.size());
  const std::vector<std::vector<double>> z = levels(L, s);
  // The seam where the tube's generatrices lean least along the layers, as on any other part: there a
  // revolution's first point lands over the one below it, not beside the seam's climb.
  Generatrices real;
  for (int i = 0; i < n; ++i) {
    real.lines.emplace_back();
    real.normals.emplace_back();
    for (size_t k = 0; k < L.t.size(); ++k) {
      real.lines.back().push_back(L.points[k][size_t(i)]);
      real.normals.back().push_back(normalAt(L, L.t[k][size_t(i)], i));
    }
  }
  const StartupProfile ramps(s.window.h, s.window.hMin, s.window.hMax);
  const int first = leastLeaningSeam(real, ramps.startRevolutions() * s.window.h);
  // The spiral builder lays its revolutions on a cylinder whose generatrices are the level axes,
  // numbered from the seam's.
  Generatrices level;
  const double radius = std::max(L.radiusMin, 1.0);
  for (int k = 0; k < n; ++k) {
    const int i = (first + k) % n;
    const Vec3 out(std::cos(layerAngle(k, n)), std::sin(layerAngle(k, n)), 0.0);
    Polyline line;
    for (double h : z[size_t(i)]) line.push_back(radius * out + h * Vec3::UnitZ());
    level.lines.push_back(std::move(line));
    level.normals.emplace_back(level.lines.back().size(), out);
  }
  // Points between layers are placed by interpolation in t, which the deposit check measures a few
  // hundredths of a millimetre off the level steps: the ramps aim that much inside the window.
  SpiralSettings aim = s.window;
  const double margin = 0.05 * (aim.hMax - aim.hMin);
  aim.hMin += margin;
  aim.hMax -= margin;
  aim.h = std::clamp(aim.h, aim.hMin, aim.hMax);
  SpiralResult laid = buildSpiral(level, aim, progress);
  std::vector<Vec3> below = L.points[0];
  for (const TrajectoryPoint& p : laid.trajectory.points) {
    const int i = (first + p.generatrix) % n;
    const std::vector<double>& zi = z[size_t(i)];
    const double h = std::clamp(p.position.z(), 0.0, zi.back());
    const size_t k =
        std::min<size_t>(size_t(std::upper_bound(zi.begin(), zi.end(), h) - zi.begin()), zi.size() - 1);
    const size_t lo = k - 1;
    const double t = levelToT(L, lo, i, h - zi[lo], zi[k] - zi[lo]);
    const Vec3 position = L.surface.at(t, layerAngle(i, n));
    if (t <= L.top[size_t(i)] + 1e-9)
      b.add(L, t, i, p.revolution, position, below[size_t(i)]);
    else
      b.close();
    if (p.revolution == 0) firstRing = b.path.size();
    below[size_t(i)] = position;
  }
  return laid.report;
}

// A sub-path's last point looks back along its own last segment, not across to the next sub-path.
void endTangents(Trajectory& path)
{
  auto& pts = path.points;
  for (size_t q = 1; q + 1 < pts.size(); ++q) {
    if (pts[q + 1].path == pts[q].path || pts[q - 1].path != pts[q].path) continue;
    const Vec3 chord = pts[q].position - pts[q - 1].position;
    Vec3 t = chord - chord.dot(pts[q].normal) * pts[q].normal;
    if (t.norm() < 1e-12) continue;
    pts[q].tangent = t.normalized();
    pts[q].build = pts[q].normal.cross(pts[q].tangent);
  }
}

void measure(SpiralReport& r, const Trajectory& path, const SpiralSettings& w)
{
  const double tol = w.heightTolerance * w.h;
  r.h = w.h, r.hMin = w.hMin, r.hMax = w.hMax, r.heightTolerance = tol;
  r.nPoints = path.size();
  r.violations.clear();
  r.modulatedViolations = 0;
  double sum = 0.0, rampMin = std::numeric_limits<double>::infinity(), rampMax = 0.0;
  r.heightMin = std::numeric_limits<double>::infinity();
  r.heightMax = -std::numeric_limits<double>::infinity();
  r.pathLength = r.maxJump = 0.0;
  for (size_t q = 0; q < path.size(); ++q) {
    const TrajectoryPoint& p = path.points[q];
    if (q > 0 && path.points[q - 1].path == p.path) {
      const double step = (p.position - path.points[q - 1].position).norm();
      r.pathLength += step;
      r.maxJump = std::max(r.maxJump, step);
    }
    const bool ramp =
        p.revolution < r.nStartupRevolutions || p.revolution >= r.nRevolutions - r.nEndRevolutions;
    const SpiralPhase phase = p.revolution < r.nStartupRevolutions ? SpiralPhase::StartUp
                              : ramp                               ? SpiralPhase::Termination
                                                                   : SpiralPhase::Modulated;
    if (ramp) {
      rampMin = std::min(rampMin, p.height);
      rampMax = std::max(rampMax, p.height);
    } else {
      r.heightMin = std::min(r.heightMin, p.height);
      r.heightMax = std::max(r.heightMax, p.height);
    }
    sum += p.height;
    if (p.height < w.hMin - tol || p.height > w.hMax + tol) {
      r.violations.push_back({q, p.revolution, p.generatrix, p.height, phase, p.height > w.hMax + tol});
      if (phase == SpiralPhase::Modulated) ++r.modulatedViolations;
    }
  }
  if (!(r.heightMin <= r.heightMax)) r.heightMin = r.heightMax = 0.0;
  r.heightMean = path.empty() ? 0.0 : sum / double(path.size());
  r.rampHeightMin = rampMax > 0.0 ? rampMin : 0.0;
  r.rampHeightMax = rampMax;
  r.feasible = r.violations.empty() && r.lengthCriterion.ok;
}

LengthCriterion lengthCriterion(const TubeLayers& L, double window)
{
  LengthCriterion c;
  c.lengthMin = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < L.top.size(); ++i) {
    double length = 0.0;
    for (size_t k = 1; k < L.t.size(); ++k)
      if (L.kept[k][i]) length += (L.points[k][i] - L.points[k - 1][i]).norm();
    c.lengthMin = std::min(c.lengthMin, length);
    c.lengthMax = std::max(c.lengthMax, length);
  }
  c.nLayers = int(L.t.size()) - 1;
  // Each generatrix's layers differ from the others' by at most the window (Eq. 3.6): here per layer,
  // since the layers are laid at their measured distances rather than at equal fractions of a length.
  double spread = 0.0;
  for (size_t k = 1; k < L.t.size(); ++k) {
    const std::vector<double> d = layerDistances(L.points[k], L.points[k - 1], L.kept[k]);
    if (d.empty()) continue;
    const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
    spread = std::max(spread, *hi - *lo);
  }
  c.stepSpread = spread;
  c.window = window;
  c.ok = spread <= window + 1e-9;
  return c;
}

LayerStats layerStats(const TubeLayers& L, const Trajectory& path)
{
  LayerStats s;
  s.layers = int(L.t.size()) - 1;
  s.deltaMin = std::numeric_limits<double>::infinity();
  s.deltaMax = 0.0;
  const int n = int(L.top.size());
  for (size_t k = 1; k < L.t.size(); ++k) {
    for (double d : layerDistances(L.points[k], L.points[k - 1], L.kept[k])) {
      s.deltaMin = std::min(s.deltaMin, d);
      s.deltaMax = std::max(s.deltaMax, d);
    }
    double worst = 0.0;
    for (int i = 0; i < n; ++i) {
      const int a = (i + n - 1) % n, c = (i + 1) % n;
      if (!L.kept[k][size_t(a)] || !L.kept[k][size_t(i)] || !L.kept[k][size_t(c)]) continue;
      worst = std::max(worst, turningAngleDeg(L.points[k], i));
    }
    s.kinkDeg.push_back(worst);
    s.maxKinkDeg = std::max(s.maxKinkDeg, worst);
  }
  if (!(s.deltaMin <= s.deltaMax)) s.deltaMin = 0.0;
  s.arcStarts = path.empty() ? 0 : path.points.back().path + 1;
  return s;
}

}  // namespace

LaidLayers layPath(const TubeLayers& L, const LayerPathSettings& s, Progress& progress)
{
  if (L.t.size() < 2) throw InputError("the tube holds no layer", "plan a part at least one deposit high");
  Builder b;
  size_t firstRing = 0;
  LaidLayers out;
  SpiralReport& r = out.path.report;
  if (s.spiral) {
    r = laySpiral(L, s, b, firstRing, progress);
  } else {
    layLayers(L, s, b, firstRing);
    r.nLayers = r.nRevolutions = int(L.t.size()) - 1;
    r.pointsPerRevolution = int(L.top.size());
  }
  if (b.path.size() < 2)
    throw InputError("no part of the path lies on the part", "check the part's upper edge");
  computeFrames(b.path);
  endTangents(b.path);
  r.normalsFlipped = orientBuildDirection(b.path, b.steps);
  computeDepositHeights(b.path, b.steps, firstRing);
  if (s.substrate)
    for (size_t q = 0; q < firstRing; ++q) {
      TrajectoryPoint& p = b.path.points[q];
      const double depth = s.substrate->depthBelow(p.position, p.build, 3.0 * s.window.h, 10.0 * s.window.h);
      if (std::isfinite(depth)) p.height = depth;
    }
  measureOnLayerBelow(b.path, firstRing, int(L.top.size()), s.window.h);
  r.lengthCriterion = lengthCriterion(L, s.window.hMax - s.window.hMin);
  r.thesisLengthCriterion = r.lengthCriterion;
  r.generatrixLengthMin = r.lengthCriterion.lengthMin;
  r.generatrixLengthMax = r.lengthCriterion.lengthMax;
  measure(r, b.path, s.window);
  out.stats = layerStats(L, b.path);
  for (size_t i = 0; i < L.top.size(); ++i) {
    Polyline line;
    for (size_t k = 0; k < L.t.size(); ++k)
      if (k == 0 || L.kept[k][i]) line.push_back(L.points[k][i]);
    out.generatrices.lines.push_back(std::move(line));
  }
  out.path.trajectory = std::move(b.path);
  return out;
}

}  // namespace spira
