#include "spira/path/tool_tilt.h"

#include <cmath>

namespace spira {

Vec3 tiltedToolAxis(const Vec3& t, const Vec3& n, const Vec3& b, double leadRad, double sideRad)
{
  if (leadRad == 0.0 && sideRad == 0.0) return b;
  const double tn = std::tan(leadRad), tt = std::tan(sideRad);
  return (tn * t + tt * n + b) / std::sqrt(1.0 + tn * tn + tt * tt);
}

Trajectory withTorchTilt(const Trajectory& path, const TorchTilt& tilt)
{
  if (!tilt.any()) return path;
  Trajectory out = path;
  const bool keepUp = path.extra.count(kUpChannels[0]) == 0;
  std::vector<double> up[3];
  for (std::vector<double>& channel : up) channel.reserve(path.size());
  for (TrajectoryPoint& p : out.points) {
    for (int k = 0; k < 3; ++k) up[k].push_back(p.build[k]);
    p.build = tiltedToolAxis(p.tangent, p.normal, p.build, tilt.leadRad, tilt.sideRad).normalized();
    const Vec3 n = p.tangent.cross(p.build);
    if (n.squaredNorm() > 1e-20) p.normal = n.normalized();
  }
  if (keepUp)
    for (int k = 0; k < 3; ++k) out.extra[kUpChannels[k]] = std::move(up[k]);
  return out;
}

Vec3 upDirection(const Trajectory& path, size_t i)
{
  const auto x = path.extra.find(kUpChannels[0]), y = path.extra.find(kUpChannels[1]),
             z = path.extra.find(kUpChannels[2]);
  if (x == path.extra.end() || y == path.extra.end() || z == path.extra.end() || i >= x->second.size() ||
      i >= y->second.size() || i >= z->second.size())
    return path.points[i].build;
  const Vec3 up(x->second[i], y->second[i], z->second[i]);
  return up.squaredNorm() > 1e-18 ? up : path.points[i].build;
}

}  // namespace spira
