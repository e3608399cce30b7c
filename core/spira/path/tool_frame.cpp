#include "spira/path/tool_frame.h"

#include <cmath>

namespace spira {

Transform toolFrame(const TrajectoryPoint& point, double spinRad)
{
  const Vec3 z = -point.build.normalized();
  Vec3 x = point.tangent - point.tangent.dot(z) * z;
  if (x.squaredNorm() < 1e-20) x = point.normal - point.normal.dot(z) * z;
  if (x.squaredNorm() < 1e-20) x = z.unitOrthogonal();
  x.normalize();
  const Vec3 y0 = z.cross(x);
  const double c = std::cos(spinRad), s = std::sin(spinRad);
  const Vec3 xs = c * x + s * y0;
  const Vec3 ys = z.cross(xs);
  Transform pose = Transform::Identity();
  pose.linear().col(0) = xs;
  pose.linear().col(1) = ys;
  pose.linear().col(2) = z;
  pose.translation() = point.position;
  return pose;
}

}  // namespace spira
