#include "spira/base/transform.h"

namespace spira {

Transform transformFromXyzZyx(const Vec3& xyz, double a, double b, double c)
{
  Transform t = Transform::Identity();
  t.linear() = (Eigen::AngleAxisd(a, Vec3::UnitZ()) * Eigen::AngleAxisd(b, Vec3::UnitY()) *
                Eigen::AngleAxisd(c, Vec3::UnitX()))
                   .toRotationMatrix();
  t.translation() = xyz;
  return t;
}

Transform transformFromXyzRpy(const Vec3& xyz, const Vec3& rpy)
{
  // URDF: R = Rz(yaw) * Ry(pitch) * Rx(roll).
  return transformFromXyzZyx(xyz, rpy.z(), rpy.y(), rpy.x());
}

}  // namespace spira
