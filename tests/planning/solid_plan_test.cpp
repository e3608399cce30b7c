// Watertight parts through the planner: a thin-walled solid planned on its mid-surface, a solid
// body refused with advice about mid-surfaces, and the real corpus solids measured against their
// own geometry (tests/data/real/SOURCES.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "builtin_plugins.h"
#include "spira/base/error.h"
#include "spira/io/import_service.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/thin_wall.h"
#include "spira/planning/planner.h"
#include "spira/planning/strategy_compare.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

PlanOutput plan(const TriangleMesh& mesh, double beadWidth = 5.2, bool midSurface = true)
{
  const MeshReport report = validateMesh(mesh);
  PlanRequest request(mesh, report);
  request.midSurfaceOfSolid = midSurface;
  request.params["process"].set("bead_width", beadWidth);
  NullProgress progress;
  return planPart(builtinRegistry(), request, progress);
}

// What a refusal says, message and hint together.
std::string refusal(const TriangleMesh& mesh, bool midSurface = true)
{
  try {
    plan(mesh, 5.2, midSurface);
  } catch (const InputError& e) {
    return std::string(e.what()) + " | " + e.hint();
  }
  return "planned";
}

TEST(SolidPlan, ThinTubeSolidIsPlannedOnItsMidSurface)
{
  const double R = 40.0, r = 36.0, H = 60.0;
  const PlanOutput out = plan(makeTubeSolid(R, r, H, 96, 20));
  ASSERT_TRUE(out.solid);
  EXPECT_NEAR(out.solid->thickness.median, R - r, 0.05);
  EXPECT_TRUE(out.solid->warnings.empty()) << out.solid->warnings.front();  // 4 mm wall, 5.2 mm bead
  EXPECT_EQ(out.topology.partClass, PartClass::Open);
  ASSERT_TRUE(out.topology.upper);
  EXPECT_NEAR(out.topology.lower.zMax, 0.0, 1e-9);
  EXPECT_NEAR(out.topology.upper->zMin, H, 1e-9);
  // The spiral runs on the middle of the wall, not on a skin.
  ASSERT_FALSE(out.spiral.trajectory.empty());
  for (size_t i = 0; i < out.spiral.trajectory.size(); i += 50) {
    const Vec3& p = out.spiral.trajectory.points[i].position;
    EXPECT_NEAR(std::hypot(p.x(), p.y()), 0.5 * (R + r), 0.1) << i;
  }
  EXPECT_TRUE(out.feasible()) << out.deposits.summary();
}

TEST(SolidPlan, WallThickerThanTheBeadAllowsIsWarnedWithBothNumbers)
{
  const PlanOutput out = plan(makeTubeSolid(40.0, 36.0, 60.0, 96, 20), 2.0);
  ASSERT_TRUE(out.solid);
  ASSERT_EQ(out.solid->warnings.size(), 1u);
  const std::string& w = out.solid->warnings.front();
  EXPECT_NE(w.find("4.00 mm thick"), std::string::npos) << w;
  EXPECT_NE(w.find("2.00 mm"), std::string::npos) << w;
  EXPECT_NE(std::find(out.warnings.begin(), out.warnings.end(), w), out.warnings.end());
}

TEST(SolidPlan, SolidBodyIsRefusedWithMidSurfaceAdviceNotRepair)
{
  const std::string text = refusal(makeRevolved({{0.0, 0.0}, {30.0, 0.0}, {30.0, 50.0}, {0.0, 50.0}}, 64));
  EXPECT_NE(text.find("solid body"), std::string::npos) << text;
  EXPECT_NE(text.find("mid-surface"), std::string::npos) << text;
  for (const char* wrong : {"fill", "repair", "hole"}) EXPECT_EQ(text.find(wrong), std::string::npos) << text;
}

TEST(SolidPlan, MidSurfaceCanBeTurnedOff)
{
  const std::string text = refusal(makeTubeSolid(40.0, 36.0, 60.0, 96, 20), false);
  EXPECT_NE(text.find("watertight"), std::string::npos) << text;
  EXPECT_NE(text.find("--no-mid-surface"), std::string::npos) << text;
}

TEST(SolidPlan, CompareRunsEveryStrategyAndThePlanarBaselineOnTheMidSurface)
{
  // Taller than wide, so the envelope strategy's skeleton is the tube's axis.
  const TriangleMesh tube = makeTubeSolid(20.0, 17.0, 80.0, 96, 40);
  const MeshReport report = validateMesh(tube);
  const PlanRequest request(tube, report);
  NullProgress progress;
  const Comparison c = compareStrategies(builtinRegistry(), request, progress);
  ASSERT_FALSE(c.strategies.empty());
  for (const StrategyOutcome& s : c.strategies) {
    EXPECT_TRUE(s.ran) << s.strategy << ": " << s.failure;
    for (size_t i = 0; i < s.points.size(); i += 50)
      EXPECT_NEAR(std::hypot(s.points[i].x(), s.points[i].y()), 18.5, 0.1) << s.strategy << " point " << i;
  }
}

ImportedPart corpus(const std::string& file)
{
  NullProgress progress;
  return importPart(builtinRegistry(), sourceDir() / "tests/data/real" / file, nullptr, progress);
}

// The adaptor's profile (read off its vertices): inner radius 14 mm all the way, outer 17.15 mm
// with a groove to 15.25 mm low down and a 16 mm top half: walls 1.25, 3.15 and 2 mm thick.
// Its outer skin is the corpus file tube_straight_wall.stl: 2 536 faces.
TEST(SolidCorpus, StraightTubeAdaptor)
{
  const ImportedPart part = corpus("tube_straight_solid.stl");
  const ThinWallAnalysis a = analyseClosedSolid(part.mesh);
  ASSERT_EQ(a.kind, SolidKind::ThinWalled) << a.reason;
  EXPECT_NEAR(a.thickness.thinnest, 1.25, 0.1);
  EXPECT_NEAR(a.thickness.thickest, 3.15, 0.1);
  EXPECT_GE(a.thickness.median, 2.0 - 0.05);
  EXPECT_LE(a.thickness.median, 3.15 + 0.05);
  EXPECT_EQ(a.midSurface.faceCount(), 2536u);
  EXPECT_EQ(validateMesh(a.midSurface).boundaryLoops.size(), 2u);
}

// A 3 mm wall all round (brute-force rays from 80 random faces: median 3.000 mm, quartiles
// 2.999 and 3.002); its outer skin is elbow_tube_wall.stl, 17 638 faces.
TEST(SolidCorpus, ElbowTube)
{
  const ImportedPart part = corpus("elbow_tube_solid.stl");
  const ThinWallAnalysis a = analyseClosedSolid(part.mesh);
  ASSERT_EQ(a.kind, SolidKind::ThinWalled) << a.reason;
  EXPECT_NEAR(a.thickness.median, 3.0, 0.02);
  EXPECT_EQ(a.midSurface.faceCount(), 17638u);
  const MeshReport mid = validateMesh(a.midSurface);
  ASSERT_EQ(mid.boundaryLoops.size(), 2u);
  EXPECT_NEAR(mid.boundaryLoops.front().zMin, 235.4, 1e-3);  // still standing on its base
}

// Thin walls (brute-force median 2.3 mm, quartiles 1.0 and 3.0 mm) on a flange with bolt holes:
// its outer skin does not make one wall, and the refusal says what to give instead.
TEST(SolidCorpus, TubeOnFlangeIsRefusedAsMoreThanOneWall)
{
  const ImportedPart part = corpus("tube_on_base_solid.stl");
  const ThinWallAnalysis a = analyseClosedSolid(part.mesh);
  ASSERT_EQ(a.kind, SolidKind::ThinWalled) << a.reason;
  EXPECT_GE(a.thickness.median, 2.0);
  EXPECT_LE(a.thickness.median, 3.0);
  PlanRequest request(part.mesh, part.report);
  request.substrateZ = 179.4;
  NullProgress progress;
  try {
    planPart(builtinRegistry(), request, progress);
    FAIL() << "the tube on its flange was planned";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not one wall"), std::string::npos) << e.what();
    EXPECT_NE(e.hint().find("flange"), std::string::npos) << e.hint();
  }
}

// A solid vase body 110 mm across (brute-force median 79 mm through it).
TEST(SolidCorpus, VaseBodyIsBulk)
{
  const ThinWallAnalysis a = analyseClosedSolid(corpus("vase_honeycomb_solid.stl").mesh);
  EXPECT_EQ(a.kind, SolidKind::Bulk) << a.reason;
  EXPECT_GT(a.thickness.median, 50.0);
}

}  // namespace
}  // namespace spira::test
