#include "spira/verify/deposit_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

#include <tbb/parallel_for.h>

#include "spira/base/number_text.h"
#include "spira/verify/segment_grid.h"
#include "spira/verify/surface_coverage.h"

namespace spira {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Height of a run's last point when material within a bead width ends it (not measured).
constexpr double kEnded = -std::numeric_limits<double>::max();
// Build directions flatter than this do not look down onto the substrate plane.
// How far below a point, in h_max, its column is searched for material. Beyond 2 h_max a point is
// in mid-air whatever lies further down, so a deeper search only sharpens the message's figure,
// while on a path with thousands of points in mid-air it crossed the whole part from each of them
// (a minute on 240 000 points).
constexpr double kReachInHMax = 10.0;

struct PathLayout {
  std::vector<Vec3> points;
  std::vector<int> run;          // -1: arc off
  std::vector<double> arc;       // path length from the start of the point's run, mm
  std::vector<char> jumped;      // the segment arriving at the point is an arc-on jump
  std::vector<size_t> material;  // segments (j, j + 1) laid as beads
  double firstJumpLength = 0.0;
};

double median(std::vector<double> v)
{
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Runs, jumps and the bead segments. A sub-path's jump length is measured on its own segments so
// that a fine and a coarse sub-path of one plan are each judged at their own scale.
PathLayout layOut(const Trajectory& path, const DepositCheckSettings& s, std::vector<DepositFlag>& flags)
{
  PathLayout L;
  const size_t n = path.size();
  L.points.resize(n);
  for (size_t i = 0; i < n; ++i) L.points[i] = path.points[i].position;
  L.run.assign(n, -1);
  L.arc.assign(n, 0.0);
  L.jumped.assign(n, 0);
  std::map<int, std::vector<double>> lengths;
  for (size_t i = 0; i + 1 < n; ++i) {
    const TrajectoryPoint &a = path.points[i], &c = path.points[i + 1];
    if (a.arcOn && c.arcOn && a.path == c.path) lengths[a.path].push_back((c.position - a.position).norm());
  }
  std::map<int, double> jumpLength;
  for (auto& [p, v] : lengths) jumpLength[p] = std::max(2.0 * s.beadWidth, 4.0 * median(v));
  L.firstJumpLength = jumpLength.empty() ? 2.0 * s.beadWidth : jumpLength.begin()->second;

  int run = -1;
  for (size_t i = 0; i < n; ++i) {
    const TrajectoryPoint& p = path.points[i];
    if (!p.arcOn) continue;
    const bool follows = i > 0 && path.points[i - 1].arcOn;
    bool newRun = !follows;
    if (follows) {
      const TrajectoryPoint& prev = path.points[i - 1];
      const double step = (p.position - prev.position).norm();
      if (prev.path != p.path) {
        newRun = true;  // each sub-path has its own arc start and stop
      } else if (step > jumpLength[p.path] || !std::isfinite(step)) {
        L.jumped[i] = 1;
        flags.push_back({i, DepositDefect::Jump, step, p.position});
        newRun = true;
      }
    }
    if (newRun) {
      ++run;
    } else {
      L.arc[i] = L.arc[i - 1] + (p.position - path.points[i - 1].position).norm();
      L.material.push_back(i - 1);
    }
    L.run[i] = run;
  }
  return L;
}

struct Column {
  Vec3 p, b, tau, nu;
};

// The point's own frame: b from the trajectory, the travel direction from its neighbours.
Column columnAt(const Trajectory& path, const PathLayout& L, size_t i)
{
  Column c;
  c.p = L.points[i];
  c.b = path.points[i].build.normalized();
  if (!c.b.allFinite() || c.b.squaredNorm() < 0.5) c.b = Vec3::UnitZ();
  const size_t prev = i > 0 && L.run[i - 1] == L.run[i] ? i - 1 : i;
  const size_t next = i + 1 < L.points.size() && L.run[i + 1] == L.run[i] ? i + 1 : i;
  Vec3 t = L.points[next] - L.points[prev];
  t -= t.dot(c.b) * c.b;
  if (t.squaredNorm() < 1e-18) {
    t = path.points[i].tangent - path.points[i].tangent.dot(c.b) * c.b;
    if (t.squaredNorm() < 1e-18) t = c.b.unitOrthogonal();
  }
  c.tau = t.normalized();
  c.nu = c.b.cross(c.tau);
  return c;
}

class HeightProbe {
 public:
  HeightProbe(const Trajectory& path, const PathLayout& L, const SegmentGrid& grid,
              const DepositCheckSettings& s, const SubstrateSurface& under, double depthEnd)
      : path_(path), L_(L), grid_(grid), s_(s), under_(under), depthEnd_(depthEnd)
  {
  }

  // The measured height of arc-on point i (kInf: nothing below).
  double height(size_t i, std::vector<uint32_t>& scratch) const
  {
    const Column c = columnAt(path_, L_, i);
    double substrate = under_.depthBelow(c.p, c.b, above(), depthEnd_);
    if (substrate < -above()) substrate = kInf;
    const double below =
        walk(i, c, substrate, scratch, [this](const Column& col, size_t j) { return crossing(col, j); });
    if (std::isfinite(below)) return below;
    // Where no segment crosses a plane under the point (a sharp turn), the nearest one passing
    // within half a bead of the column counts.
    return walk(i, c, kInf, scratch, [this](const Column& col, size_t j) { return closest(col, j); });
  }

  // Distance from the point to the nearest material laid before it, up to `reach`.
  double nearestMaterial(size_t i, double reach, std::vector<uint32_t>& scratch) const
  {
    const Vec3& p = L_.points[i];
    scratch.clear();
    grid_.collect(p.array() - reach, p.array() + reach, scratch);
    double best = kInf;
    for (uint32_t s : scratch) {
      const size_t j = grid_.from(s);
      if (laidBefore(j, i)) best = std::min(best, pointSegmentDistance(p, L_.points[j], L_.points[j + 1]));
    }
    return best;
  }

 private:
  double above() const { return 3.0 * s_.hMax; }
  double radius() const { return 0.5 * s_.beadWidth; }

  bool laidBefore(size_t segment, size_t i) const
  {
    const size_t end = segment + 1;
    if (end >= i) return false;
    return L_.run[end] != L_.run[i] || L_.arc[i] - L_.arc[end] >= s_.beadWidth;
  }

  // Material laid with the build direction turned away from the point's, by more than 120 degrees,
  // lies across the part's hollow (the far side of a ring around a pole), not over or under the point.
  // Nearer square to it, it is the other arm of a sharp turn of the same wall (a constant-distance
  // layer's kink), which folds over the point.
  bool sameSide(const Column& c, size_t j) const { return path_.points[j].build.dot(c.b) > -0.5; }

  // Depth of the segment where it crosses the plane normal to the travel direction, within half a
  // bead of the wall; kInf where it does not.
  double crossing(const Column& c, size_t j) const
  {
    const auto [a, e] = beadSpan(j);
    const double da = c.tau.dot(a - c.p), de = c.tau.dot(e - c.p);
    if ((da > 0.0 && de > 0.0) || (da < 0.0 && de < 0.0) || da == de) return kInf;
    const Vec3 x = a + (da / (da - de)) * (e - a);
    if (std::abs(c.nu.dot(x - c.p)) > radius()) return kInf;
    // A segment that climbs more than a quarter of its advance is a spiral's seam: the layer under
    // the point is the end of the seam nearer it along the travel (a hair off that end, the
    // crossing would read the climb as the layer).
    if (std::abs(c.b.dot(e - a)) > 0.25 * std::abs(da - de))
      return c.b.dot(c.p - (std::abs(da) <= std::abs(de) ? a : e));
    return c.b.dot(c.p - x);
  }

  // Segment j, reaching half of itself further where it starts or ends its run: each point stands
  // for the bead half a step either side of it, the run's end points too, so the plane across a
  // point laid a hair behind the run's first point (a spiral's second revolution over its arc
  // start) still meets the bead there.
  std::pair<Vec3, Vec3> beadSpan(size_t j) const
  {
    Vec3 a = L_.points[j], e = L_.points[j + 1];
    const Vec3 cap = 0.5 * (e - a);
    if (j == 0 || L_.run[j - 1] != L_.run[j]) a -= cap;
    if (j + 2 >= L_.points.size() || L_.run[j + 2] != L_.run[j + 1]) e += cap;
    return {a, e};
  }

  // Depth of the segment's closest approach to the column, when within half a bead of it.
  double closest(const Column& c, size_t j) const
  {
    const Vec3 &a = L_.points[j], &e = L_.points[j + 1];
    const Vec3 d = e - a, w0 = a - c.p;
    const double dd = d.dot(d), db = d.dot(c.b), denom = dd - db * db;
    const double u = denom > 1e-18 ? std::clamp((db * c.b.dot(w0) - d.dot(w0)) / denom, 0.0, 1.0) : 0.0;
    const Vec3 off = a + u * d - c.p;
    const double t = -off.dot(c.b);
    return (off + t * c.b).norm() > radius() ? kInf : t;
  }

  // The segments near the column's stretch [t0, t0 + step], once each.
  void near(const Column& c, double t0, std::vector<uint32_t>& scratch) const
  {
    const double step = grid_.cell();
    const Vec3 top = c.p - t0 * c.b, bottom = c.p - (t0 + step) * c.b;
    scratch.clear();
    grid_.collect(top.cwiseMin(bottom).array() - radius(), top.cwiseMax(bottom).array() + radius(), scratch);
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
  }

  // Walks down the column one cell at a time, keeping the shallowest depth `depthOf` gives a
  // segment laid before the point: every depth in a cell's stretch comes from a segment within the
  // stretch's box grown by half a bead, so once one no deeper than the stretch is found, deeper
  // stretches cannot change it. Starts from `best` (the substrate, when it lies under the point).
  template <typename DepthOf>
  double walk(size_t i, const Column& c, double best, std::vector<uint32_t>& scratch, DepthOf depthOf) const
  {
    const double step = grid_.cell();
    for (double t0 = -above(); t0 < depthEnd_ && best > t0; t0 += step) {
      near(c, t0, scratch);
      for (uint32_t s : scratch) {
        const size_t j = grid_.from(s);
        if (!laidBefore(j, i) || !sameSide(c, j)) continue;
        const double t = depthOf(c, j);
        if (t >= -above() && t < best) best = t;
      }
    }
    return best;
  }

  const Trajectory& path_;
  const PathLayout& L_;
  const SegmentGrid& grid_;
  const DepositCheckSettings& s_;
  const SubstrateSurface& under_;
  double depthEnd_;
};

// A run's last arc-on point, or a lone one.
bool runEnds(const PathLayout& L, size_t i)
{
  return i + 1 >= L.run.size() || L.run[i + 1] != L.run[i];
}

DepositDefect classify(double h, const DepositCheckSettings& s, bool* ok)
{
  *ok = false;
  if (h < 0.0) return DepositDefect::BelowDeposit;
  if (h < s.hMin - s.tolerance) return DepositDefect::Thin;
  if (h <= s.hMax + s.tolerance) {
    *ok = true;
    return DepositDefect::Thin;
  }
  if (h <= 2.0 * s.hMax) return DepositDefect::Thick;
  return DepositDefect::Unsupported;
}

std::string describe(const DepositFlag& f, double searchDepth)
{
  const std::string where = "point " + std::to_string(f.point) + " at " + pointText(f.position, 1) + " mm";
  switch (f.kind) {
    case DepositDefect::BelowDeposit:
      return where + " lies " + fixedText(-f.height, 2) + " mm under material already laid";
    case DepositDefect::Thin:
      return where + " would lay a " + fixedText(f.height, 2) + " mm bead";
    case DepositDefect::Thick:
      return where + " would need a " + fixedText(f.height, 2) + " mm bead";
    case DepositDefect::Unsupported:
      return where + (std::isfinite(f.height)
                          ? " is " + fixedText(f.height, 2) + " mm above the material below it"
                          : " has nothing within " + fixedText(searchDepth, 0) + " mm below it");
    case DepositDefect::Jump:
      return where + " is reached by a " + fixedText(f.height, 2) + " mm jump with the arc on";
  }
  return where;
}

}  // namespace

const char* depositDefectName(DepositDefect kind)
{
  switch (kind) {
    case DepositDefect::BelowDeposit:
      return "below_deposit";
    case DepositDefect::Thin:
      return "thin";
    case DepositDefect::Thick:
      return "thick";
    case DepositDefect::Unsupported:
      return "unsupported";
    case DepositDefect::Jump:
      return "jump";
  }
  return "unsupported";
}

std::string DepositCheckReport::summary() const
{
  if (feasible) return "every bead is supported inside the window and the surface is covered";
  std::ostringstream o;
  const char* names[5] = {"under material already laid", "thinner than h_min", "thicker than h_max",
                          "in mid-air (nothing within 2 h_max below)", "reached by an arc-on jump"};
  std::string sep;
  for (int k = 0; k < 5; ++k) {
    if (counts[k] == 0) continue;
    const auto first = std::find_if(flags.begin(), flags.end(),
                                    [k](const DepositFlag& f) { return static_cast<int>(f.kind) == k; });
    o << sep << counts[k] << " point(s) " << names[k] << " (first: " << describe(*first, searchDepth) << ")";
    sep = "; ";
  }
  if (coverageChecked && uncoveredArea > 0.0)
    o << sep << fixedText(100.0 * uncoveredFraction(), 1) << " % of the surface ("
      << fixedText(uncoveredArea, 0) << " mm^2) is not covered, up to " << fixedText(largestGap, 1)
      << " mm from the path at " << pointText(largestGapAt, 1) << " mm";
  return o.str();
}

DepositCheckReport checkDeposits(const Trajectory& path, const TriangleMesh* surface,
                                 const DepositCheckSettings& settings, Progress& progress)
{
  DepositCheckReport r;
  std::vector<DepositFlag> flags;
  const PathLayout L = layOut(path, settings, flags);
  r.jumpLength = L.firstJumpLength;
  const double cell = std::max({settings.beadWidth, settings.hMax, 1e-3});
  const SegmentGrid grid(L.points, L.material, cell, 0.0);
  BoundingBox box = finiteBounds(L.points.data(), L.points.size());
  const bool onMesh = settings.substrate && !settings.substrate->isPlane();
  const SubstrateSurface under = onMesh ? *settings.substrate : SubstrateSurface::plane(settings.substrateZ);
  if (onMesh) {
    const TriangleMesh& m = *settings.substrate->surfaceMesh();
    const BoundingBox reach = finiteBounds(m.vertices.data(), m.vertices.size());
    box.extend(reach.min);
    box.extend(reach.max);
  } else {
    box.extend(Vec3(box.min.x(), box.min.y(), std::min(box.min.z(), settings.substrateZ)));
  }

  const size_t n = path.size();
  const double reach = kReachInHMax * settings.hMax;
  r.searchDepth = reach;
  std::vector<double> height(n, 0.0);
  progress.report(0.0, "deposit check");
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 512), [&](const auto& range) {
    if (progress.cancelled()) return;
    std::vector<uint32_t> scratch;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if (!path.points[i].arcOn) continue;
      const Vec3& p = L.points[i];
      const Vec3 b = path.points[i].build.normalized();
      double depthEnd = 0.0;  // the column's length down to the far side of the box
      for (int k = 0; k < 8; ++k) {
        const Vec3 corner((k & 1) ? box.max.x() : box.min.x(), (k & 2) ? box.max.y() : box.min.y(),
                          (k & 4) ? box.max.z() : box.min.z());
        depthEnd = std::max(depthEnd, b.allFinite() ? b.dot(p - corner) : 0.0);
      }
      const HeightProbe probe(path, L, grid, settings, under, std::min(depthEnd, reach) + cell);
      if (runEnds(L, i)) {
        // Nothing is laid after a run's last point: its bead ends on what lies within a bead
        // width (a closed part's closure point fills the centre of its last ring).
        const double gap = probe.nearestMaterial(i, settings.beadWidth, scratch);
        height[i] = gap <= settings.beadWidth ? kEnded : probe.height(i, scratch);
      } else {
        height[i] = probe.height(i, scratch);
      }
    }
  });
  progress.checkCancel();

  double sum = 0.0, lo = kInf, hi = -kInf;
  size_t supported = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!path.points[i].arcOn) continue;
    ++r.pointsChecked;
    if (height[i] == kEnded) continue;
    const double h = height[i];
    if (std::isfinite(h)) {
      ++supported;
      sum += h;
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
    bool ok = false;
    const DepositDefect kind = classify(h, settings, &ok);
    if (!ok) {
      flags.push_back({i, kind, h, L.points[i]});
      continue;
    }
    r.plannedDifferenceMax = std::max(r.plannedDifferenceMax, std::abs(h - path.points[i].height));
  }
  if (supported) {
    r.heightMin = lo;
    r.heightMax = hi;
    r.heightMean = sum / supported;
  }
  std::stable_sort(flags.begin(), flags.end(),
                   [](const DepositFlag& a, const DepositFlag& b) { return a.point < b.point; });
  for (const DepositFlag& f : flags) ++r.counts[static_cast<int>(f.kind)];
  r.flags = std::move(flags);

  if (surface && !surface->empty()) {
    progress.report(0.7, "surface coverage");
    r.coverRadius = std::max(settings.hMax, 0.5 * settings.beadWidth) + settings.tolerance;
    const SurfaceCoverage c = measureCoverage(
        *surface, L.points, grid, r.coverRadius, settings.hMax,
        {onMesh ? -kInf : settings.substrateZ, 0.5 * settings.beadWidth, settings.hMax, settings.tolerance},
        progress);
    r.coverageChecked = true;
    r.surfaceArea = c.area;
    r.uncoveredArea = c.uncoveredArea;
    r.largestGap = c.largestGap;
    r.largestGapAt = c.largestGapAt;
  }
  r.feasible = r.flags.empty() && r.uncoveredFraction() <= settings.maxUncoveredFraction;
  progress.report(1.0, "deposit check");
  return r;
}

}  // namespace spira
