// The source's tilt law (Chalvin Eq. 2.30-2.32, validation case V11): the closed form against the
// printed construction (a Rodrigues rotation of the local z axis), its two planes, and a tilted path.
#include <gtest/gtest.h>

#include <cmath>

#include "spira/base/units.h"
#include "spira/path/tool_tilt.h"

namespace spira {
namespace {

// Eq. 2.30-2.32 as printed: theta_T = atan2(sqrt(tan^2 t + tan^2 n), 1), k = (tan t / rho, -tan n / rho, 0),
// T = [0 0 1] R(k, theta_T), a row vector times the Rodrigues matrix, i.e. its third row, in (t, n, b).
Vec3 printedToolAxis(const Vec3& t, const Vec3& n, const Vec3& b, double lead, double side)
{
  const double tn = std::tan(lead), tt = std::tan(side);
  const double rho = std::sqrt(tn * tn + tt * tt);
  if (rho == 0.0) return b;
  const double theta = std::atan2(rho, 1.0);
  const Vec3 k(tt / rho, -tn / rho, 0.0);
  Mat3 K;
  K << 0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0;
  const Mat3 R = Mat3::Identity() + std::sin(theta) * K + (1.0 - std::cos(theta)) * K * K;
  const Vec3 local = R.row(2).transpose();
  return local.x() * t + local.y() * n + local.z() * b;
}

// A direct frame (t, n, b) with b = n x t, turned off the axes so no component is special.
void someFrame(Vec3& t, Vec3& n, Vec3& b)
{
  const Mat3 turn = (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) *
                     Eigen::AngleAxisd(-1.1, Vec3(0.3, -1, 0.2).normalized()))
                        .toRotationMatrix();
  t = turn * Vec3::UnitY();
  n = turn * Vec3::UnitX();
  b = n.cross(t);
}

TEST(ToolTilt, ClosedFormEqualsThePrintedRotation)
{
  Vec3 t, n, b;
  someFrame(t, n, b);
  for (double lead : {-30.0, -7.5, 0.0, 4.0, 20.0, 44.0})
    for (double side : {-40.0, -3.0, 0.0, 12.0, 35.0}) {
      const Vec3 closed = tiltedToolAxis(t, n, b, degToRad(lead), degToRad(side));
      const Vec3 printed = printedToolAxis(t, n, b, degToRad(lead), degToRad(side));
      EXPECT_NEAR((closed - printed).norm(), 0.0, 1e-12) << lead << " " << side;
      EXPECT_NEAR(closed.norm(), 1.0, 1e-12);
    }
  EXPECT_EQ(tiltedToolAxis(t, n, b, 0.0, 0.0), b);
}

// Each angle alone leans the torch by itself in its own plane: lead in (t, b), side in (n, b).
TEST(ToolTilt, EachAngleLeansTheTorchInItsPlane)
{
  Vec3 t, n, b;
  someFrame(t, n, b);
  const Vec3 lead = tiltedToolAxis(t, n, b, degToRad(15.0), 0.0);
  EXPECT_NEAR(radToDeg(std::acos(lead.dot(b))), 15.0, 1e-9);
  EXPECT_NEAR(lead.dot(n), 0.0, 1e-12);
  EXPECT_GT(lead.dot(t), 0.0);  // pushing: towards the travel direction
  const Vec3 side = tiltedToolAxis(t, n, b, 0.0, degToRad(-25.0));
  EXPECT_NEAR(radToDeg(std::acos(side.dot(b))), 25.0, 1e-9);
  EXPECT_NEAR(side.dot(t), 0.0, 1e-12);
  EXPECT_LT(side.dot(n), 0.0);
  // Both: tan of each plane's angle is kept, T ~ (tan lead, tan side, 1).
  const Vec3 both = tiltedToolAxis(t, n, b, degToRad(10.0), degToRad(20.0));
  EXPECT_NEAR(both.dot(t) / both.dot(b), std::tan(degToRad(10.0)), 1e-12);
  EXPECT_NEAR(both.dot(n) / both.dot(b), std::tan(degToRad(20.0)), 1e-12);
}

TEST(ToolTilt, ATiltedPathKeepsItsBuildDirectionForThePositioner)
{
  Trajectory path;
  for (int i = 0; i < 36; ++i) {
    const double a = degToRad(10.0 * i);
    TrajectoryPoint p;
    p.position = Vec3(40 * std::cos(a), 40 * std::sin(a), 0.05 * i);
    p.normal = Vec3(std::cos(a), std::sin(a), 0);
    p.tangent = Vec3(-std::sin(a), std::cos(a), 0);
    p.build = p.normal.cross(p.tangent);
    path.points.push_back(p);
  }
  EXPECT_EQ(withTorchTilt(path, TorchTilt{}), path);
  const Trajectory tilted = withTorchTilt(path, TorchTilt{degToRad(10.0), degToRad(5.0)});
  ASSERT_EQ(tilted.size(), path.size());
  for (size_t i = 0; i < path.size(); ++i) {
    const TrajectoryPoint& a = path.points[i];
    const TrajectoryPoint& p = tilted.points[i];
    EXPECT_EQ(p.position, a.position);
    EXPECT_EQ(p.tangent, a.tangent);
    EXPECT_NEAR(
        (p.build - tiltedToolAxis(a.tangent, a.normal, a.build, degToRad(10.0), degToRad(5.0))).norm(), 0.0,
        1e-12);
    EXPECT_NEAR(p.normal.dot(p.build), 0.0, 1e-12);
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-12);
    EXPECT_NEAR((upDirection(tilted, i) - a.build).norm(), 0.0, 1e-15);
    EXPECT_EQ(upDirection(path, i), a.build);
  }
  // Tilting again keeps the first build direction, not the first tilt's torch axis.
  const Trajectory twice = withTorchTilt(tilted, TorchTilt{0.0, degToRad(3.0)});
  EXPECT_NEAR((upDirection(twice, 7) - path.points[7].build).norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace spira
