#include <gtest/gtest.h>

#include <cmath>

#include "builtin_plugins.h"
#include "spira/base/progress.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/placement_frame.h"
#include "spira/planning/planner.h"
#include "spira/plugin/plugin_registry.h"

namespace spira::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

Transform rotationAbout(const Vec3& axis, double angle)
{
  Transform T = Transform::Identity();
  T.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  return T;
}

PlanOutput planMesh(const TriangleMesh& mesh, int lowerLoop = -1)
{
  const MeshReport report = validateMesh(mesh);
  PlanRequest request(mesh, report);
  request.lowerLoopOverride = lowerLoop;
  request.params["decomposer.isovalue"].set("points_per_rev", std::int64_t{90});
  NullProgress progress;
  return planPart(builtinRegistry(), request, progress);
}

// A cylinder stored lying on its side (its own z horizontal) and placed upright in the world must
// plan exactly like the upright cylinder: same points, seen through the placement.
TEST(PlacementFrame, ATiltedPartIsPlannedWithTheWorldsUp)
{
  const TriangleMesh upright = makeOpenCylinder(30.0, 40.0, 96, 16);
  const Transform T_world_part = rotationAbout(Vec3::UnitX(), kPi / 2.0);
  const TriangleMesh lying = upright.transformed(T_world_part.inverse());
  ASSERT_LT(std::abs(lying.vertices[0].z() - upright.vertices[0].y()), 1e-9);  // really lying

  const PlacementFrame frame(T_world_part);
  ASSERT_FALSE(frame.identity());
  PlanOutput placed = planMesh(frame.toBuild(lying));
  frame.toPart(placed.spiral.trajectory);
  const PlanOutput reference = planMesh(upright);

  const auto& got = placed.spiral.trajectory.points;
  const auto& want = reference.spiral.trajectory.points;
  ASSERT_EQ(got.size(), want.size());
  ASSERT_GT(got.size(), 1000u);
  double worst = 0.0, worstBuild = 0.0;
  for (size_t i = 0; i < got.size(); ++i) {
    worst = std::max(worst, (T_world_part * got[i].position - want[i].position).norm());
    worstBuild = std::max(worstBuild, (T_world_part.linear() * got[i].build - want[i].build).norm());
    EXPECT_EQ(got[i].revolution, want[i].revolution);
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(worstBuild, 1e-9);
  // In the part frame the build direction is the part's own +y (world z turned back).
  EXPECT_NEAR(got[got.size() / 2].build.y(), 1.0, 1e-3);
}

TEST(PlacementFrame, NoTiltMeansNoConversion)
{
  Transform T = rotationAbout(Vec3::UnitZ(), 0.0);
  T.translation() = Vec3(10.0, -5.0, 3.0);
  EXPECT_TRUE(PlacementFrame(T).identity());
  EXPECT_FALSE(PlacementFrame(rotationAbout(Vec3::UnitZ(), 0.3)).identity());
}

// Turned upside down, the cylinder's former top loop is the lowest: the loop the user chose in the
// part frame must still be the one planned from.
TEST(PlacementFrame, TheChosenBaseLoopFollowsTheTilt)
{
  const TriangleMesh part = makeOpenCylinder(30.0, 40.0, 64, 8);
  const PlacementFrame frame(rotationAbout(Vec3::UnitX(), kPi));
  const TriangleMesh build = frame.toBuild(part);
  const MeshReport partReport = validateMesh(part);
  const MeshReport buildReport = validateMesh(build);
  ASSERT_EQ(partReport.boundaryLoops.size(), 2u);
  ASSERT_EQ(buildReport.boundaryLoops.size(), 2u);
  EXPECT_NEAR(partReport.boundaryLoops[0].zMin, 0.0, 1e-9);   // the part's own base
  EXPECT_NEAR(buildReport.boundaryLoops[1].zMax, 0.0, 1e-9);  // is the top once turned over
  EXPECT_EQ(PlacementFrame::loopIndexInBuild(partReport.boundaryLoops, buildReport.boundaryLoops, 0), 1);
  EXPECT_EQ(PlacementFrame::loopIndexInBuild(partReport.boundaryLoops, buildReport.boundaryLoops, 1), 0);
  EXPECT_EQ(PlacementFrame::loopIndexInBuild(partReport.boundaryLoops, buildReport.boundaryLoops, -1), -1);
  EXPECT_EQ(PlacementFrame::loopIndexInBuild(partReport.boundaryLoops, buildReport.boundaryLoops, 7), -1);
}

}  // namespace
}  // namespace spira::test
