#include "real/deposit_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "real/segment_grid.h"

namespace spira::test::real {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A run is a maximal stretch of consecutive arc-on points with one sub-path index; -1 = arc off.
std::vector<int> runIds(const std::vector<PathPoint>& pts)
{
  std::vector<int> run(pts.size(), -1);
  int current = -1;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (!pts[i].arc) continue;
    const bool continues = i > 0 && pts[i - 1].arc && pts[i - 1].path == pts[i].path;
    if (!continues) ++current;
    run[i] = current;
  }
  return run;
}

bool sameRun(const std::vector<int>& run, size_t i, size_t j)
{
  return run[i] >= 0 && run[i] == run[j];
}

// Any unit vector perpendicular to b.
V3 perpendicular(const V3& b)
{
  const V3 seed = std::abs(b.x) < 0.9 ? V3(1, 0, 0) : V3(0, 1, 0);
  return (seed - b * seed.dot(b)).unit();
}

// Depth along b of the closest approach between the line p + s b and the segment [a, c], if the
// two come within `reach`. Depth is b·(p - y), y the segment's closest point.
std::optional<double> closestApproachDepth(const V3& p, const V3& b, const V3& a, const V3& c, double reach)
{
  const V3 d = c - a;
  const V3 r = a - p;
  const double dd = d.dot(d), bd = b.dot(d), br = b.dot(r), dr = d.dot(r);
  const double den = dd - bd * bd;  // |b| = 1
  double u = den > 1e-12 ? (bd * br - dr) / den : 0.0;
  u = std::clamp(u, 0.0, 1.0);
  const V3 y = a + d * u;
  const double s = b.dot(y - p);
  if ((y - (p + b * s)).norm() > reach) return std::nullopt;
  return -s;
}

double median(std::vector<double> v)
{
  if (v.empty()) return 0.0;
  const size_t m = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(m), v.end());
  return v[m];
}

struct Heights {
  std::vector<double> h;  // per point, NaN where nothing lies below or the arc is off
  // A run's last point with material laid within a bead width of it: it ends its bead there and
  // its height is not judged (see "Measured deposit height").
  std::vector<bool> ended;
};

// Measured deposit height at every arc-on point (see "Measured deposit height").
Heights measureHeights(const std::vector<PathPoint>& pts, const std::vector<int>& run, const CheckSettings& s)
{
  const size_t n = pts.size();
  const double w = s.beadWidth, half = 0.5 * w, lowest = -3.0 * s.hMax;
  // Arc length along each run, to hold back the bead being laid beside a point.
  std::vector<double> arcLen(n, 0.0);
  for (size_t i = 1; i < n; ++i)
    if (sameRun(run, i, i - 1)) arcLen[i] = arcLen[i - 1] + (pts[i].p - pts[i - 1].p).norm();

  const double reach = std::sqrt(half * half + lowest * lowest) + 1e-9;
  V3 lo = n ? pts[0].p : V3{}, hi = lo;
  for (const auto& q : pts) {
    lo = V3(std::min(lo.x, q.p.x), std::min(lo.y, q.p.y), std::min(lo.z, q.p.z));
    hi = V3(std::max(hi.x, q.p.x), std::max(hi.y, q.p.y), std::max(hi.z, q.p.z));
  }
  const double extent = (hi - lo).norm();
  SegmentGrid grid(std::max(reach, 1.0));
  std::vector<size_t> material;  // segment j = (p_j, p_j+1)
  size_t next = 0;               // the first segment start not yet laid down as material
  Heights out{std::vector<double>(n, kNaN), std::vector<bool>(n, false)};
  for (size_t i = 0; i < n; ++i) {
    if (run[i] < 0) continue;
    // Lay down every segment that ended before i: all of the runs before this one, and of this
    // run those whose far end lies at least w of path behind p_i.
    while (next + 1 < n && next < i) {
      if (!sameRun(run, next, next + 1)) {
        ++next;
        continue;
      }
      if (run[next] == run[i] && arcLen[i] - arcLen[next + 1] < w) break;
      grid.add(next, pts[next].p, pts[next + 1].p);
      ++next;
    }
    const V3& p = pts[i].p;
    const V3 b = pts[i].b.unit();
    const V3 prev = i > 0 && sameRun(run, i, i - 1) ? pts[i - 1].p : p;
    const V3 after = i + 1 < n && sameRun(run, i, i + 1) ? pts[i + 1].p : p;
    V3 tau = after - prev;
    tau = (tau - b * tau.dot(b)).unit();
    if (tau.norm() == 0) tau = perpendicular(b);
    const V3 nu = b.cross(tau);

    // The substrate is one more crossing.
    double best = std::numeric_limits<double>::infinity();
    if (b.z >= 0.1) {
      const double t = (p.z - s.substrateZ) / b.z;
      if (t >= lowest) best = t;
    }
    auto crossings = [&](const V3& centre, double radius) {
      grid.query(centre, radius, [&](size_t j) {
        // A point stands for the bead half a step either side of it, a run's end points too.
        V3 a = pts[j].p, c = pts[j + 1].p;
        const V3 cap = (c - a) * 0.5;
        if (j == 0 || !sameRun(run, j - 1, j)) a = a - cap;
        if (j + 2 >= n || !sameRun(run, j + 1, j + 2)) c = c + cap;
        const double sa = tau.dot(a - p), sc = tau.dot(c - p);
        if (sa * sc > 0 || sa == sc) return;
        const V3 x = a + (c - a) * (sa / (sa - sc));
        if (std::abs(nu.dot(x - p)) > half) return;
        // A spiral's seam climbs steeply: it is measured at its end nearer the plane.
        const bool seam = std::abs(b.dot(c - a)) > 0.25 * std::abs(sc - sa);
        const double t = b.dot(p - (seam ? (std::abs(sa) < std::abs(sc) ? a : c) : x));
        if (t >= lowest) best = std::min(best, t);
      });
    };
    crossings(p, reach);
    // A crossing deeper than the reach still counts (the point is then unsupported, not judged
    // by the fallback): walk down the torch axis one stretch at a time before falling back.
    for (double t0 = reach; !std::isfinite(best) && t0 < extent; t0 += reach)
      crossings(p - b * (t0 + 0.5 * reach), 0.5 * reach + half);
    if (!std::isfinite(best)) {
      // Nothing crosses (a sharp turn, a closure point): what passes near the torch axis counts.
      grid.query(p, reach, [&](size_t j) {
        if (const auto t = closestApproachDepth(p, b, pts[j].p, pts[j + 1].p, half); t && *t >= lowest)
          best = std::min(best, *t);
      });
    }
    if (std::isfinite(best)) out.h[i] = best;
    if (i + 1 >= n || !sameRun(run, i, i + 1)) {
      double gap = std::numeric_limits<double>::infinity();
      grid.query(p, w, [&](size_t j) {
        gap = std::min(gap, (p - closestOnSegment(p, pts[j].p, pts[j + 1].p)).norm());
      });
      out.ended[i] = gap <= w;
    }
  }
  return out;
}

// Segments with the arc on across them longer than J within a sub-path (see "Verdict"). A new sub-path
// starts its own arc: the program travels to it with the arc off, so its first segment is no jump.
std::vector<bool> jumps(const std::vector<PathPoint>& pts, double beadWidth)
{
  std::vector<std::pair<int, double>> lengths;  // (sub-path, arc-on segment length)
  for (size_t i = 1; i < pts.size(); ++i)
    if (pts[i].arc && pts[i - 1].arc && pts[i].path == pts[i - 1].path)
      lengths.push_back({pts[i].path, (pts[i].p - pts[i - 1].p).norm()});
  std::vector<bool> out(pts.size(), false);
  std::vector<std::pair<int, double>> limit;  // (sub-path, J)
  auto limitOf = [&](int path) {
    for (const auto& [k, j] : limit)
      if (k == path) return j;
    std::vector<double> own;
    for (const auto& [k, len] : lengths)
      if (k == path) own.push_back(len);
    const double j = std::max(2.0 * beadWidth, 4.0 * median(own));
    limit.push_back({path, j});
    return j;
  };
  for (size_t i = 1; i < pts.size(); ++i) {
    if (!pts[i].arc || !pts[i - 1].arc) continue;
    out[i] = pts[i].path == pts[i - 1].path && (pts[i].p - pts[i - 1].p).norm() > limitOf(pts[i].path);
  }
  return out;
}

void measureCoverage(const std::vector<PathPoint>& pts, const std::vector<int>& run, const CheckSettings& s,
                     const std::vector<Triangle>& surface, CheckResult& r)
{
  const double reach = std::max(s.hMax, 0.5 * s.beadWidth) + s.tol;
  SegmentGrid grid(reach);
  for (size_t j = 0; j + 1 < pts.size(); ++j)
    if (sameRun(run, j, j + 1)) grid.add(j, pts[j].p, pts[j + 1].p);
  auto distance = [&](const V3& q, double radius) {
    double d = std::numeric_limits<double>::infinity();
    grid.query(q, radius,
               [&](size_t j) { d = std::min(d, (q - closestOnSegment(q, pts[j].p, pts[j + 1].p)).norm()); });
    return d;
  };
  // A sample on the substrate under a bead laid at most h_max above it, within w / 2 sideways.
  const double halfWidth = 0.5 * s.beadWidth;
  auto onFootprint = [&](const V3& q) {
    if (std::abs(q.z - s.substrateZ) > s.tol) return false;
    bool covered = false;
    grid.query(q, std::hypot(halfWidth, s.hMax) + s.tol, [&](size_t j) {
      const V3 a = pts[j].p, c = pts[j + 1].p;
      const double dx = c.x - a.x, dy = c.y - a.y, len2 = dx * dx + dy * dy;
      const double t = len2 > 0 ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
      const V3 x = a + (c - a) * t;
      if (std::hypot(x.x - q.x, x.y - q.y) <= halfWidth && x.z <= s.substrateZ + s.hMax + s.tol)
        covered = true;
    });
    return covered;
  };
  r.coverageChecked = true;
  for (const Triangle& t : surface) {
    const double area = 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
    r.surfaceArea += area;
    const double edge = std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
    const int m = std::max(1, static_cast<int>(std::ceil(edge / s.hMax)));
    const double share = area / (0.5 * (m + 1) * (m + 2));
    for (int a = 0; a <= m; ++a)
      for (int b = 0; a + b <= m; ++b) {
        const double u = static_cast<double>(a) / m, v = static_cast<double>(b) / m;
        const V3 q = t[0] * (1 - u - v) + t[1] * u + t[2] * v;
        double d = distance(q, reach);
        if (d <= reach || onFootprint(q)) continue;
        r.uncoveredArea += share;
        // How far the path is from here, widening the search up to 64 times the reach.
        for (double radius = 2 * reach; !std::isfinite(d) && radius <= 64 * reach; radius *= 2)
          d = distance(q, radius);
        r.maxDistance = std::max(r.maxDistance, std::isfinite(d) ? d : 64 * reach);
      }
  }
}

}  // namespace

const char* flagName(Flag f)
{
  switch (f) {
    case Flag::Unsupported:
      return "unsupported";
    case Flag::Thin:
      return "thin";
    case Flag::Thick:
      return "thick";
    case Flag::BelowDeposit:
      return "below_deposit";
    case Flag::Jump:
      return "jump";
  }
  return "?";
}

std::string CheckResult::counts() const
{
  std::ostringstream o;
  o << unsupported << " unsupported, " << thin << " thin, " << thick << " thick, " << below << " below, "
    << jump << " jump";
  if (coverageChecked) o << ", " << 100.0 * uncoveredFraction() << " % uncovered";
  return o.str();
}

std::string CheckResult::summary() const
{
  std::ostringstream o;
  o << checked << " arc-on points: " << unsupported << " unsupported, " << thin << " thin, " << thick
    << " thick, " << below << " below_deposit, " << jump << " jump";
  if (checked > unsupported)
    o << "; H " << heightMin << " .. " << heightMax << " mm (mean " << heightMean << ")";
  if (coverageChecked)
    o << "; uncovered " << 100.0 * uncoveredFraction() << " % of " << surfaceArea << " mm2 (max distance "
      << maxDistance << " mm)";
  for (const Offender& f : firstOffenders)
    o << "\n  point " << f.index << " " << flagName(f.flag) << " H=" << f.height << " at (" << f.p.x << ", "
      << f.p.y << ", " << f.p.z << ")";
  return o.str();
}

CheckResult checkDeposit(const std::vector<PathPoint>& points, const CheckSettings& settings,
                         const std::vector<Triangle>& surface)
{
  CheckResult r;
  const std::vector<int> run = runIds(points);
  const Heights heights = measureHeights(points, run, settings);
  const std::vector<bool> jumped = jumps(points, settings.beadWidth);
  double sum = 0;
  size_t measured = 0;
  r.heightMin = std::numeric_limits<double>::infinity();
  r.heightMax = -std::numeric_limits<double>::infinity();
  auto flag = [&](size_t i, Flag f) {
    if (r.firstOffenders.size() < 10) r.firstOffenders.push_back({i, f, heights.h[i], points[i].p});
  };
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].arc) continue;
    ++r.checked;
    const double h = heights.h[i];
    if (heights.ended[i]) {
      // Its bead ends on material within a bead width: its height is not judged.
    } else if (std::isnan(h) || h > 2.0 * settings.hMax) {
      ++r.unsupported;
      flag(i, Flag::Unsupported);
    } else {
      sum += h;
      ++measured;
      r.heightMin = std::min(r.heightMin, h);
      r.heightMax = std::max(r.heightMax, h);
      if (h < 0) {
        ++r.below;
        flag(i, Flag::BelowDeposit);
      } else if (h < settings.hMin - settings.tol) {
        ++r.thin;
        flag(i, Flag::Thin);
      } else if (h > settings.hMax + settings.tol) {
        ++r.thick;
        flag(i, Flag::Thick);
      }
    }
    if (jumped[i]) {
      ++r.jump;
      flag(i, Flag::Jump);
    }
  }
  if (measured > 0) {
    r.heightMean = sum / static_cast<double>(measured);
  } else {
    r.heightMin = r.heightMax = 0;
  }
  if (!surface.empty()) measureCoverage(points, run, settings, surface, r);
  return r;
}

}  // namespace spira::test::real
