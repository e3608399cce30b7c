#include "projection_axis.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"

namespace spira {

namespace {

// Per mm of height, how far x and y move along the stretch from `from` to `to`; zero when the
// stretch is flatter than 60 degrees from vertical (extrapolating it would run away sideways).
Vec3 slope(const Vec3& from, const Vec3& to)
{
  const Vec3 d = to - from;
  const double dz = d.z();
  if (!(std::abs(dz) >= 0.5 * d.norm()) || dz == 0.0) return Vec3::Zero();
  return Vec3(d.x() / dz, d.y() / dz, 0.0);
}

// The point of the chain at arc length `s` from its start (clamped to the chain).
Vec3 atArcLength(const Polyline& c, double s)
{
  for (size_t i = 1; i < c.size(); ++i) {
    const double l = (c[i] - c[i - 1]).norm();
    if (s <= l && l > 0) return c[i - 1] + (s / l) * (c[i] - c[i - 1]);
    s -= l;
  }
  return c.back();
}

}  // namespace

ProjectionAxis ProjectionAxis::vertical(const Vec3& point)
{
  ProjectionAxis a;
  a.points_ = {point, point + Vec3::UnitZ()};
  a.vertical_ = true;
  return a;
}

ProjectionAxis ProjectionAxis::line(const Vec3& a, const Vec3& b)
{
  if (a.z() == b.z())
    throw InputError("the projection axis is horizontal, so it gives no point per height",
                     "use the iso-value strategy (--strategy isovalue) for this part");
  ProjectionAxis out;
  out.points_ = a.z() < b.z() ? Polyline{a, b} : Polyline{b, a};
  out.below_ = out.above_ = slope(out.points_[0], out.points_[1]);
  return out;
}

ProjectionAxis ProjectionAxis::chain(const Polyline& points)
{
  if (points.size() < 2)
    throw InputError("the skeleton chain has fewer than two points", "check the part's skeleton");
  Polyline p = points;
  if (p.front().z() > p.back().z()) std::reverse(p.begin(), p.end());
  for (size_t i = 1; i < p.size(); ++i) p[i].z() = std::max(p[i].z(), p[i - 1].z());
  if (!(p.back().z() > p.front().z()))
    throw InputError("the skeleton does not rise, so it gives no point per height",
                     "use the iso-value strategy (--strategy isovalue) for this part");
  ProjectionAxis out;
  double length = 0.0;
  for (size_t i = 1; i < p.size(); ++i) length += (p[i] - p[i - 1]).norm();
  // The end directions over a tenth of the chain: long enough to average out node jitter.
  Polyline reversed(p.rbegin(), p.rend());
  out.below_ = slope(atArcLength(p, 0.1 * length), p.front());
  out.above_ = slope(atArcLength(reversed, 0.1 * length), p.back());
  out.points_ = std::move(p);
  return out;
}

Eigen::Vector2d ProjectionAxis::at(double z) const
{
  const Vec3& lo = points_.front();
  const Vec3& hi = points_.back();
  if (vertical_) return Eigen::Vector2d(lo.x(), lo.y());
  if (z <= lo.z())
    return Eigen::Vector2d(lo.x() + below_.x() * (z - lo.z()), lo.y() + below_.y() * (z - lo.z()));
  if (z >= hi.z())
    return Eigen::Vector2d(hi.x() + above_.x() * (z - hi.z()), hi.y() + above_.y() * (z - hi.z()));
  // First point strictly above z; the segment before it contains z.
  const auto it = std::upper_bound(points_.begin(), points_.end(), z,
                                   [](double value, const Vec3& p) { return value < p.z(); });
  const Vec3& b = *it;
  const Vec3& a = *(it - 1);
  const double t = b.z() > a.z() ? (z - a.z()) / (b.z() - a.z()) : 0.0;
  return Eigen::Vector2d(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
}

}  // namespace spira
