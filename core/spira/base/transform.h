#pragma once

#include <Eigen/Geometry>

namespace spira {

// A rigid transform. Names say direction: T_a_b maps coordinates expressed in frame b into
// frame a (p_a = T_a_b * p_b), so T_a_c = T_a_b * T_b_c.
using Transform = Eigen::Isometry3d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

inline Transform identityTransform()
{
  return Transform::Identity();
}

// Translation (mm) followed by intrinsic rotations about Z, Y', X'' (radians): the KUKA A, B, C order.
Transform transformFromXyzZyx(const Vec3& xyz, double a, double b, double c);
// Translation (mm) and fixed-axis roll/pitch/yaw about X, Y, Z (radians): the URDF rpy order.
Transform transformFromXyzRpy(const Vec3& xyz, const Vec3& rpy);

}  // namespace spira
