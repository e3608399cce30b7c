#include <cmath>

#include <gtest/gtest.h>

#include "builtin_plugins.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/level_base.h"
#include "spira/planning/part_topology.h"
#include "spira/planning/plan_advice.h"
#include "spira/planning/planner.h"

namespace spira::test {
namespace {

constexpr double kRadius = 40.0, kHeight = 100.0, kSlant = 10.0;
constexpr int kAround = 120;

// A tube cut at a slant at its base, as a scan is: the base edge runs from z = 0 (x = -R) to
// z = kSlant (x = +R), the top stays at z = kHeight, and the rows in between are spread evenly.
TriangleMesh slantCutTube()
{
  TriangleMesh m = makeOpenCylinder(kRadius, kHeight, kAround, 50);
  for (Vec3& v : m.vertices) {
    const double base = 0.5 * kSlant * (1.0 + v.x() / kRadius);
    v.z() = base + (kHeight - base) * v.z() / kHeight;
  }
  return m;
}

TEST(LevelBase, ASlantBaseIsRefusedWithItsRiseAndTheCutThatLevelsIt)
{
  const TriangleMesh tube = slantCutTube();
  const MeshReport report = validateMesh(tube);
  PlanRequest request(tube, report);
  NullProgress progress;
  try {
    planPart(builtinRegistry(), request, progress);
    FAIL() << "a base edge rising 10 mm off the plate was planned";
  } catch (const BaseNotLevelError& e) {
    const std::string what = e.what(), hint = e.hint();
    EXPECT_NE(what.find("not level: it runs from z 0.00 to 10.00 mm"), std::string::npos) << what;
    EXPECT_NE(what.find("at most 0.90 mm"), std::string::npos) << what;
    EXPECT_NE(hint.find("cut the part level at z = 10.00 mm"), std::string::npos) << hint;
    EXPECT_NE(hint.find("--level-base"), std::string::npos) << hint;
    // The advice plans the levelled part and finds it feasible.
    const PlanAdvice advice = adviseLevelBase(builtinRegistry(), request, e, progress);
    EXPECT_TRUE(advice.found) << advice.text();
    EXPECT_EQ(advice.flags, "--level-base");
    EXPECT_NE(advice.text().find("planned and checked feasible"), std::string::npos) << advice.text();
  }
}

TEST(LevelBase, TheCutLeavesALevelEdgeTheRightAreaAndAPlannablePart)
{
  const TriangleMesh tube = slantCutTube();
  const PartTopology topology = findPartTopology(validateMesh(tube), tube, 0.0);
  LevelledBase levelled = levelBase(tube, topology.lower);
  EXPECT_DOUBLE_EQ(levelled.cutZ, kSlant);
  EXPECT_DOUBLE_EQ(levelled.removed, kSlant);
  const MeshReport report = validateMesh(levelled.mesh);
  ASSERT_EQ(report.boundaryLoops.size(), 2u);
  EXPECT_EQ(report.componentCount, 1u);
  EXPECT_DOUBLE_EQ(report.boundaryLoops[0].zMin, kSlant);
  EXPECT_DOUBLE_EQ(report.boundaryLoops[0].zMax, kSlant);
  // What is left is the 120-gon prism from z = 10 to 100.
  const double prism = kAround * 2.0 * kRadius * std::sin(kPi / kAround) * (kHeight - kSlant);
  EXPECT_NEAR(report.area, prism, 1e-6 * prism);

  for (Vec3& v : levelled.mesh.vertices) v.z() -= levelled.cutZ;
  const MeshReport standing = validateMesh(levelled.mesh);
  PlanRequest request(levelled.mesh, standing);
  NullProgress progress;
  const PlanOutput plan = planPart(builtinRegistry(), request, progress);
  EXPECT_TRUE(plan.feasible()) << plan.deposits.summary();
  EXPECT_NEAR(plan.deposits.heightMin, 1.8, 0.01);
}

}  // namespace
}  // namespace spira::test
