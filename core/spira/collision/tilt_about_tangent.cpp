#include "spira/collision/tilt_about_tangent.h"

#include <cmath>

namespace spira {

TrajectoryPoint tiltAboutTangent(const TrajectoryPoint& point, double angleRad)
{
  if (angleRad == 0.0) return point;
  const double tn = point.tangent.norm();
  if (!(tn > 1e-12)) return point;
  const Vec3 t = point.tangent / tn;
  Vec3 b = point.build - point.build.dot(t) * t;
  if (!(b.norm() > 1e-12)) return point;
  b.normalize();
  TrajectoryPoint out = point;
  out.tangent = t;
  out.build = std::cos(angleRad) * b + std::sin(angleRad) * t.cross(b);
  out.normal = t.cross(out.build);
  return out;
}

}  // namespace spira
