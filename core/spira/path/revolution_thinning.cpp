#include "spira/path/revolution_thinning.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "spira/base/error.h"

namespace spira {
namespace {

struct Run {
  size_t begin = 0, end = 0;
  size_t size() const { return end - begin; }
};

Vec3 unitLerp(const Vec3& a, const Vec3& b, double w, const Vec3& fallback)
{
  const Vec3 v = (1.0 - w) * a + w * b;
  const double n = v.norm();
  return n > 1e-12 ? Vec3(v / n) : fallback;
}

// One wire feed over the arc-on points: the process held the wire feed and modulated the travel.
bool heldWireFeed(const Trajectory& t, const Run& band)
{
  double lo = 1e300, hi = 0.0;
  for (size_t i = band.begin; i < band.end; ++i)
    if (t.points[i].arcOn) {
      lo = std::min(lo, t.points[i].wireFeed);
      hi = std::max(hi, t.points[i].wireFeed);
    }
  return hi <= lo * (1.0 + 1e-9);
}

}  // namespace

ThinningResult thinRevolutions(const Trajectory& planned, const ThinningZone& zone)
{
  std::map<int, Run> runs;
  for (size_t i = 0; i < planned.size(); ++i) {
    const TrajectoryPoint& p = planned.points[i];
    if (p.path != zone.path) continue;
    auto [it, fresh] = runs.try_emplace(p.revolution, Run{i, i + 1});
    if (!fresh) it->second.end = i + 1;
  }
  const std::string band = "revolutions " + std::to_string(zone.first) + " to " + std::to_string(zone.last) +
                           " of path " + std::to_string(zone.path);
  if (zone.first < 0 || zone.last <= zone.first || !runs.count(zone.first) || !runs.count(zone.last))
    throw InputError("the trajectory has no " + band, "thin a band of revolutions the path has");
  if (!(zone.ratio > 0.0 && zone.ratio <= 1.0))
    throw InputError("a thinning ratio must lie in (0, 1], found " + std::to_string(zone.ratio));
  const size_t q = runs[zone.first].size();
  for (int r = zone.first; r <= zone.last; ++r)
    if (!runs.count(r) || runs[r].size() != q)
      throw InputError(band + " do not all have " + std::to_string(q) + " points",
                       "thin only the revolutions that visit every generatrix");

  const int steps = zone.last - zone.first;
  const int count = int(std::ceil(steps / zone.ratio - 1e-9));
  ThinningResult out;
  out.ratio = double(steps) / count;
  out.revolutionsAdded = count - steps;
  out.first = zone.first;
  out.last = zone.first + count;
  const bool synergic = heldWireFeed(planned, Run{runs[zone.first].begin, runs[zone.last].end});

  // Deposit laid on each generatrix from the band's base up to revolution r: heights summed.
  const auto at = [&](int r, size_t k) -> const TrajectoryPoint& {
    return planned.points[runs[r].begin + k];
  };
  std::vector<std::vector<double>> climbed(size_t(steps) + 1, std::vector<double>(q, 0.0));
  for (int s = 1; s <= steps; ++s)
    for (size_t k = 0; k < q; ++k)
      climbed[size_t(s)][k] = climbed[size_t(s) - 1][k] + at(zone.first + s, k).height;
  // Where generatrix k has climbed `c` of its band: the planned step s holding it and how far into it.
  const auto locate = [&](double c, size_t k) {
    int s = 0;
    while (s + 1 < steps && climbed[size_t(s) + 1][k] < c) ++s;
    const double step = climbed[size_t(s) + 1][k] - climbed[size_t(s)][k];
    return std::pair{s, step > 0.0 ? std::clamp((c - climbed[size_t(s)][k]) / step, 0.0, 1.0) : 1.0};
  };
  Trajectory& t = out.trajectory;
  const size_t keepEnd = runs[zone.first].end, resume = runs[zone.last].end;
  t.points.assign(planned.points.begin(), planned.points.begin() + long(keepEnd));
  for (const auto& [name, values] : planned.extra)
    t.extra[name].assign(values.begin(), values.begin() + long(keepEnd));
  for (int j = 1; j <= count; ++j) {
    for (size_t k = 0; k < q; ++k) {
      // Each generatrix lays its band in equal layers: the ramps that level the band's ends are
      // spread over it rather than thinned further.
      const double layer = climbed[size_t(steps)][k] / count;
      const auto [s, w] = j == count ? std::pair{steps - 1, 1.0} : locate(j * layer, k);
      const TrajectoryPoint& a = at(zone.first + s, k);
      const TrajectoryPoint& b = at(zone.first + s + 1, k);
      TrajectoryPoint p = b;
      p.position = (1.0 - w) * a.position + w * b.position;
      p.normal = unitLerp(a.normal, b.normal, w, b.normal);
      const Vec3 along = unitLerp(a.tangent, b.tangent, w, b.tangent);
      const Vec3 across = along - along.dot(p.normal) * p.normal;
      p.tangent = across.norm() > 1e-12 ? Vec3(across.normalized()) : b.tangent;
      p.build = p.normal.cross(p.tangent).normalized();
      p.revolution = zone.first + j;
      p.height = layer;
      // The planned step this point falls in sets the cross-section it scales.
      const double scale = b.height > 0.0 ? p.height / b.height : 1.0;
      if (synergic)
        p.travelSpeed = b.travelSpeed / scale;
      else
        p.wireFeed = b.wireFeed * scale;
      t.points.push_back(p);
      const size_t ia = runs[zone.first + s].begin + k, ib = runs[zone.first + s + 1].begin + k;
      for (const auto& [name, values] : planned.extra)
        t.extra[name].push_back((1.0 - w) * values[ia] + w * values[ib]);
    }
  }
  for (size_t i = resume; i < planned.size(); ++i) {
    TrajectoryPoint p = planned.points[i];
    if (p.path == zone.path) p.revolution += out.revolutionsAdded;
    t.points.push_back(p);
    for (const auto& [name, values] : planned.extra) t.extra[name].push_back(values[i]);
  }
  return out;
}

}  // namespace spira
