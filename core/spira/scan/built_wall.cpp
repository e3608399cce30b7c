#include "spira/scan/built_wall.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/scan/point_grid.h"

namespace spira {
namespace {

constexpr size_t kNone = std::numeric_limits<size_t>::max();

void requireAt(const Trajectory& plan, size_t at)
{
  if (at == 0 || at > plan.size())
    throw InputError(
        "index " + std::to_string(at) + " is outside the plan's points 1.." + std::to_string(plan.size()),
        "give the number of points deposited, from 1 to " + std::to_string(plan.size()));
}

}  // namespace

double DepositErrors::relativeAt(const Trajectory& plan, size_t i) const
{
  if (double(i) >= until * double(plan.size())) return 0.0;
  if (kind == Kind::Uniform) return relative;
  const double facing = plan.points[i].normal.normalized().dot(side.normalized());
  return relative * std::max(0.0, facing);
}

std::vector<size_t> pointsBelow(const Trajectory& plan)
{
  std::vector<size_t> below(plan.size(), kNone);
  std::map<std::pair<int, int>, size_t> last;  // (sub-path, generatrix) -> latest point
  for (size_t i = 0; i < plan.size(); ++i) {
    const std::pair<int, int> key(plan.points[i].path, plan.points[i].generatrix);
    const auto it = last.find(key);
    if (it != last.end()) below[i] = it->second;
    last[key] = i;
  }
  return below;
}

std::vector<double> builtShortfall(const Trajectory& plan, size_t at, const DepositErrors& errors)
{
  requireAt(plan, at);
  const std::vector<size_t> below = pointsBelow(plan);
  std::vector<double> shortfall(at, 0.0);
  for (size_t i = 0; i < at; ++i) {
    const double carried = below[i] == kNone ? 0.0 : shortfall[below[i]];
    shortfall[i] = carried - errors.relativeAt(plan, i) * plan.points[i].height;
  }
  return shortfall;
}

PointCloud scanOfBuild(const Trajectory& plan, size_t at, const std::vector<double>& shortfall,
                       double beadWidth, int revolutions, double depth, double noiseMm, std::uint64_t seed)
{
  requireAt(plan, at);
  if (shortfall.size() < at) throw InternalError("a shortfall for fewer points than were built");
  // The beads within `revolutions` of the top of their generatrix.
  const std::vector<size_t> below = pointsBelow(plan);
  // 2: the last bead on its generatrix, whose crown the scanner sees; 1: a bead under it, of which only
  // the wall's faces show; 3: deeper, not scanned.
  std::vector<char> covered(at, 0);
  for (size_t i = at; i-- > 0;) {
    if (covered[i]) continue;
    int k = 0;
    for (size_t j = i; j != kNone; j = below[j], ++k) covered[j] = k == 0 ? 2 : k < revolutions ? 1 : 3;
  }
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0.0, noiseMm > 0.0 ? noiseMm : 1.0);
  const auto jitter = [&] { return noiseMm > 0.0 ? noise(random) : 0.0; };
  const double r = 0.5 * beadWidth;
  const int crown = 13;
  const int faces = std::max(1, int(std::ceil(depth / (0.25 * beadWidth))));
  PointCloud out;
  for (size_t i = 0; i < at; ++i) {
    if (covered[i] == 3 || !plan.points[i].arcOn) continue;
    const TrajectoryPoint& p = plan.points[i];
    const Vec3 b = p.build.normalized();
    const Vec3 n = (p.normal - p.normal.dot(b) * b).normalized();
    const Vec3 centre = p.position - b * (shortfall[i] + r);
    for (int k = 0; k < (covered[i] == 2 ? crown : 0); ++k) {
      const double phi = kPi * double(k) / double(crown - 1);
      const Vec3 radial = std::cos(phi) * n + std::sin(phi) * b;
      out.points.push_back(centre + (r + jitter()) * radial);
    }
    for (int k = 1; k <= faces; ++k) {
      const Vec3 down = centre - b * (depth * double(k) / double(faces));
      out.points.push_back(down + (r + jitter()) * n);
      out.points.push_back(down - (r + jitter()) * n);
    }
  }
  return out;
}

MeasuredEdge measureTopEdge(const Trajectory& plan, size_t at, const PointCloud& scan, double beadWidth)
{
  requireAt(plan, at);
  MeasuredEdge edge;
  std::map<std::pair<int, int>, size_t> last;
  for (size_t i = 0; i < at; ++i)
    if (plan.points[i].arcOn) last[{plan.points[i].path, plan.points[i].generatrix}] = i;
  for (const auto& [key, i] : last) edge.points.push_back(i);
  std::sort(edge.points.begin(), edge.points.end());
  const double r = 0.5 * beadWidth;
  edge.shortfall.assign(edge.points.size(), NAN);
  edge.samples.assign(edge.points.size(), 0);
  // Half a bead width: the line's neighbourhood spans a few cells, each with few points off it.
  const PointGrid grid(scan.points, r);
  std::vector<double> tops;
  std::vector<std::uint32_t> near;
  for (size_t e = 0; e < edge.points.size(); ++e) {
    const size_t i = edge.points[e];
    const TrajectoryPoint& p = plan.points[i];
    const Vec3 b = p.build.normalized();
    const Vec3 n = (p.normal - p.normal.dot(b) * b).normalized();
    const Vec3 t = b.cross(n);
    const double step =
        0.5 * std::max(i + 1 < plan.size() ? (plan.points[i + 1].position - p.position).norm() : 0.0,
                       i > 0 ? (p.position - plan.points[i - 1].position).norm() : 0.0);
    const double along = std::max(step, 0.25 * r);
    tops.clear();
    near.clear();
    // Any height along b: a wall far below the plan is still under its point. The grid hands over
    // the points near that line; the test below is the one that decides.
    grid.nearLine(p.position, b, std::hypot(0.5 * r, along), near);
    for (const std::uint32_t k : near) {
      const Vec3 d = scan.points[k] - p.position;
      const double across = d.dot(n);
      if (std::abs(across) > 0.5 * r || std::abs(d.dot(t)) > along) continue;
      // The crown's top above this sample, for a half circle of radius r.
      tops.push_back(d.dot(b) + r - std::sqrt(r * r - across * across));
    }
    if (tops.empty()) continue;
    // The highest bead's samples: those within a quarter bead width of the top tenth (the beads below
    // show only their faces, which lie lower; a stray point above moves a percentile, not a median).
    std::sort(tops.begin(), tops.end());
    const double high = tops[tops.size() - 1 - tops.size() / 10];
    const auto from = std::lower_bound(tops.begin(), tops.end(), high - 0.5 * r);
    const std::vector<double> crown(from, tops.end());
    edge.samples[e] = crown.size();
    edge.shortfall[e] = -crown[crown.size() / 2];
  }
  // Points the scan missed take their neighbours' value along the edge.
  for (size_t e = 0; e < edge.points.size(); ++e) {
    if (!std::isnan(edge.shortfall[e])) continue;
    ++edge.unmeasured;
    double before = NAN, after = NAN;
    size_t db = 0, da = 0;
    for (size_t k = e; k-- > 0;)
      if (!std::isnan(edge.shortfall[k]) && edge.samples[k] > 0) {
        before = edge.shortfall[k], db = e - k;
        break;
      }
    for (size_t k = e + 1; k < edge.points.size(); ++k)
      if (edge.samples[k] > 0) {
        after = edge.shortfall[k], da = k - e;
        break;
      }
    if (!std::isnan(before) && !std::isnan(after))
      edge.shortfall[e] = (before * double(da) + after * double(db)) / double(da + db);
    else
      edge.shortfall[e] = std::isnan(before) ? after : before;
  }
  if (edge.unmeasured == edge.points.size())
    throw InputError("the scan covers none of the " + std::to_string(edge.points.size()) +
                         " last beads laid before point " + std::to_string(at),
                     "scan the top of the wall as it stands, in the part's frame (scan-compare aligns a scan "
                     "taken elsewhere)");
  return edge;
}

}  // namespace spira
