#include "spira/collision/torch_solid.h"

#include <algorithm>
#include <cmath>

namespace spira {

TorchSolid::TorchSolid(const TorchParams& p, const Transform& T_part_tcp)
    : tcp_(T_part_tcp.translation()), axis_(-T_part_tcp.linear().col(2).normalized())
{
  const double s0 = p.standoff, s1 = s0 + p.coneLength, s2 = s1 + p.bodyLength;
  centers_[0] = tcp_ + s0 * axis_;
  centers_[1] = tcp_ + s1 * axis_;
  centers_[2] = tcp_ + s2 * axis_;
  radii_[0] = p.nozzleRadius;
  radii_[1] = p.bodyRadius;
  radii_[2] = p.bodyRadius;
}

Vec3 TorchSolid::support(const Vec3& d) const
{
  Vec3 radial = d - d.dot(axis_) * axis_;
  // For d (nearly) along the axis the difference above is rounding noise with an axial part of its
  // own size; normalised, it would put the point off the rim, outside the torch, and GJK's distance
  // bounds would be wrong. Projecting again keeps the point on the rim.
  radial -= radial.dot(axis_) * axis_;
  const double rn = radial.norm();
  // Along the axis every rim point ties: any radial direction will do.
  radial = rn > 1e-12 * d.norm() ? Vec3(radial / rn) : axis_.unitOrthogonal();
  int best = 0;
  double bestValue = d.dot(centers_[0]) + radii_[0] * rn;
  for (int k = 1; k < 3; ++k) {
    const double value = d.dot(centers_[k]) + radii_[k] * rn;
    if (value > bestValue) {
      bestValue = value;
      best = k;
    }
  }
  return centers_[best] + radii_[best] * radial;
}

BoundingBox TorchSolid::bounds() const
{
  // A circle of radius r about unit axis a spans r * sqrt(1 - a_k^2) along world axis k.
  const Vec3 spread = (Vec3::Ones() - axis_.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
  BoundingBox box;
  for (int k = 0; k < 3; ++k) {
    box.extend(centers_[k] - radii_[k] * spread);
    box.extend(centers_[k] + radii_[k] * spread);
  }
  return box;
}

bool TorchSolid::boundingCapsule(Vec3& a, Vec3& b, double& radius) const
{
  a = centers_[0];
  b = centers_[2];
  radius = std::max({radii_[0], radii_[1], radii_[2]});
  return true;
}

double TorchSolid::heightAbove(const Vec3& point, const Vec3& normal) const
{
  return normal.dot(support(-normal) - point);
}

}  // namespace spira
