#include <gtest/gtest.h>

#include "builtin_plugins.h"
#include "spira/base/error.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/part_topology.h"
#include "spira/planning/planner.h"

namespace spira::test {
namespace {

TriangleMesh raised(TriangleMesh m, double dz)
{
  for (Vec3& v : m.vertices) v.z() += dz;
  return m;
}

// A vase standing below the plate (base at z = -90.8, rim at z = 0, as CAD exports with the
// origin at the rim put it): its base is still the lowest loop, never the rim next to z = 0.
TEST(PartBase, TheLowestLoopIsTheBaseWhereverTheSubstrateIs)
{
  const TriangleMesh cone = raised(makeOpenCone(30.0, 45.0, 90.8, 72, 30), -90.8);
  const MeshReport report = validateMesh(cone);
  const PartTopology t = findPartTopology(report, cone, 0.0);
  EXPECT_NEAR(t.lower.zMax, -90.8, 1e-9);
  EXPECT_NEAR(t.upper->zMin, 0.0, 1e-9);
  EXPECT_NEAR(t.lowerGapToSubstrate, -90.8, 1e-9);
}

TEST(PartBase, APartAwayFromTheSubstrateIsRefusedWithTheGapAndTheFlags)
{
  const TriangleMesh cone = raised(makeOpenCone(30.0, 45.0, 90.8, 72, 30), -90.8);
  const MeshReport report = validateMesh(cone);
  PlanRequest request(cone, report);
  NullProgress progress;
  try {
    planPart(builtinRegistry(), request, progress);
    FAIL() << "a part 90.8 mm under the plate was planned";
  } catch (const InputError& e) {
    const std::string what = e.what(), hint = e.hint();
    EXPECT_NE(what.find("90.80 mm below the substrate"), std::string::npos) << what;
    EXPECT_NE(hint.find("--drop"), std::string::npos) << hint;
    EXPECT_NE(hint.find("--substrate-z -90.80"), std::string::npos) << hint;
  }
  // Floating 5 mm above it: the same refusal, the other way.
  const TriangleMesh floating = raised(makeOpenCylinder(30.0, 40.0, 72, 16), 5.0);
  const MeshReport floatingReport = validateMesh(floating);
  PlanRequest up(floating, floatingReport);
  try {
    planPart(builtinRegistry(), up, progress);
    FAIL() << "a part 5 mm above the plate was planned";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("5.00 mm above the substrate"), std::string::npos) << e.what();
  }
  // The suggested substrate height plans it.
  up.substrateZ = 5.0;
  EXPECT_TRUE(planPart(builtinRegistry(), up, progress).feasible());
}

TEST(PartBase, AMissingLoopIsNamedAsInfoNumbersIt)
{
  const TriangleMesh tube = makeOpenCylinder(30.0, 40.0, 72, 16);
  const MeshReport report = validateMesh(tube);
  try {
    findPartTopology(report, tube, 0.0, 2);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("loop 3 does not exist"), std::string::npos) << e.what();
    EXPECT_NE(e.hint().find("loops 1 to 2"), std::string::npos) << e.hint();
  }
}

}  // namespace
}  // namespace spira::test
