#include <gtest/gtest.h>

#include <cmath>

#include "spira/path/tool_frame.h"

namespace spira {
namespace {

TrajectoryPoint wallPoint()
{
  // A point on the outside of a vertical cylinder wall at +X, travelling +Y, building +Z.
  TrajectoryPoint p;
  p.position = Vec3(50, 0, 10);
  p.normal = Vec3::UnitX();
  p.tangent = Vec3::UnitY();
  p.build = Vec3::UnitZ();
  return p;
}

TEST(ToolFrame, TorchPointsDownTheBuildDirectionAndXFollowsTravel)
{
  const Transform f = toolFrame(wallPoint());
  EXPECT_NEAR((f.linear().col(2) - Vec3(0, 0, -1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((f.linear().col(0) - Vec3(0, 1, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((f.linear().col(1) - Vec3(1, 0, 0)).norm(), 0.0, 1e-15);  // z x x = -Z x Y = +X
  EXPECT_NEAR((f.translation() - Vec3(50, 0, 10)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(f.linear().determinant(), 1.0, 1e-14);
}

TEST(ToolFrame, SpinTurnsAboutTheTorchAxisOnly)
{
  const double spin = 0.7;
  const Transform f0 = toolFrame(wallPoint());
  const Transform f = toolFrame(wallPoint(), spin);
  EXPECT_NEAR((f.linear().col(2) - f0.linear().col(2)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(f.linear().col(0).dot(f0.linear().col(0)), std::cos(spin), 1e-14);
  // Right-handed spin about z = -Z: +X of spin 0 (=+Y) turns towards +X... z x x0 = y0 = +X.
  EXPECT_NEAR(f.linear().col(0).dot(f0.linear().col(1)), std::sin(spin), 1e-14);
}

TEST(ToolFrame, TravelAlongTheTorchAxisFallsBackToTheNormal)
{
  TrajectoryPoint p = wallPoint();
  p.tangent = Vec3::UnitZ();
  const Transform f = toolFrame(p);
  EXPECT_NEAR((f.linear().col(0) - Vec3::UnitX()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(f.linear().determinant(), 1.0, 1e-14);
}

}  // namespace
}  // namespace spira
