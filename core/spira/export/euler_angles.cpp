#include "spira/export/euler_angles.h"

#include <cmath>

#include "spira/base/units.h"

namespace spira {

namespace {

// Below this cos(y) the matrix is at gimbal lock: r(0,0) and r(1,0) carry no direction any more.
// An exact lock built from y = pi/2 in double precision leaves cos(y) near 6e-17.
constexpr double kGimbalLockCos = 1e-12;

}  // namespace

ZyxAngles zyxAnglesFromRotation(const Mat3& r)
{
  ZyxAngles out;
  const double cosY = std::hypot(r(0, 0), r(1, 0));
  if (cosY < kGimbalLockCos) {
    // R = Rz(z) Ry(+-90) Rx(x) depends on x -+ z only; with x = 0, r(0,1) = -sin z, r(1,1) = cos z.
    out.y = r(2, 0) < 0.0 ? kPi / 2.0 : -kPi / 2.0;
    out.z = std::atan2(-r(0, 1), r(1, 1));
    out.x = 0.0;
    return out;
  }
  out.z = std::atan2(r(1, 0), r(0, 0));
  out.y = std::atan2(-r(2, 0), cosY);
  out.x = std::atan2(r(2, 1), r(2, 2));
  return out;
}

Mat3 rotationFromZyxAngles(const ZyxAngles& angles)
{
  return (Eigen::AngleAxisd(angles.z, Vec3::UnitZ()) * Eigen::AngleAxisd(angles.y, Vec3::UnitY()) *
          Eigen::AngleAxisd(angles.x, Vec3::UnitX()))
      .toRotationMatrix();
}

KukaAbc kukaAbcFromRotation(const Mat3& r)
{
  const ZyxAngles z = zyxAnglesFromRotation(r);
  return {z.z, z.y, z.x};
}

Mat3 rotationFromKukaAbc(const KukaAbc& abc)
{
  return rotationFromZyxAngles({abc.a, abc.b, abc.c});
}

FanucWpr fanucWprFromRotation(const Mat3& r)
{
  const ZyxAngles z = zyxAnglesFromRotation(r);
  return {z.x, z.y, z.z};
}

Mat3 rotationFromFanucWpr(const FanucWpr& wpr)
{
  return rotationFromZyxAngles({wpr.r, wpr.p, wpr.w});
}

double rotationAngleBetween(const Mat3& a, const Mat3& b)
{
  // Through the quaternion, which stays accurate for tiny angles where acos(trace) does not.
  return Eigen::AngleAxisd(Eigen::Quaterniond(a.transpose() * b).normalized()).angle();
}

}  // namespace spira
