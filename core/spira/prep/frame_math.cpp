#include "spira/prep/frame_math.h"

namespace spira {

void orthonormaliseFrame(TrajectoryPoint& point)
{
  Vec3 b = point.build;
  if (b.squaredNorm() < 1e-24) b = point.normal.cross(point.tangent);
  if (b.squaredNorm() < 1e-24) b = Vec3::UnitZ();
  b.normalize();
  Vec3 t = point.tangent - point.tangent.dot(b) * b;
  if (t.squaredNorm() < 1e-20) t = b.cross(point.normal);
  if (t.squaredNorm() < 1e-20) t = b.unitOrthogonal();
  t.normalize();
  point.build = b;
  point.tangent = t;
  point.normal = t.cross(b);
}

Eigen::Quaterniond frameQuaternion(const TrajectoryPoint& point)
{
  Mat3 r;
  r.col(0) = point.normal;
  r.col(1) = point.tangent;
  r.col(2) = point.build;
  return Eigen::Quaterniond(r);
}

}  // namespace spira
