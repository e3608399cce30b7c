#include <gtest/gtest.h>

#include <string>

#include "builtin_plugins.h"
#include "spira/base/error.h"
#include "spira/io/import_service.h"
#include "spira/planning/branch_refusal.h"
#include "spira/planning/level_base.h"
#include "spira/planning/planner.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

std::vector<BoundaryLoop> loopsOf(std::initializer_list<double> lengths)
{
  std::vector<BoundaryLoop> loops;
  for (double l : lengths) {
    BoundaryLoop b;
    b.length = l;
    loops.push_back(b);
  }
  return loops;
}

std::string refusal(const std::vector<BoundaryLoop>& loops, double minPerimeter, double beadWidth)
{
  try {
    refuseUnbranchedPart(loops, minPerimeter, beadWidth);
  } catch (const InputError& e) {
    return e.fullMessage();
  }
  return "no refusal";
}

// The scanned artery of the corpus: free edges of 7.9, 8.4 and 15.7 mm under a 5.2 mm bead, whose
// ring is 16.3 mm. Its branches are slender, not holes: the message names each short edge (numbered
// from 1 as `info` lists them) and the bead that would lay them, 7.9 / pi = 2.5 mm.
TEST(BranchRefusal, FreeEdgesShorterThanABeadRingAreNamedAsSlenderBranchesNotHoles)
{
  const std::string m = refusal(loopsOf({7.91, 8.44, 15.68}), 16.34, 5.2);
  EXPECT_NE(m.find("free edge 1 is 7.9 mm around"), std::string::npos) << m;
  EXPECT_NE(m.find("free edge 3 is 15.7 mm around"), std::string::npos) << m;
  EXPECT_NE(m.find("16.3 mm, pi x the 5.2 mm bead width"), std::string::npos) << m;
  EXPECT_NE(m.find("narrower than 2.5 mm (--bead-width)"), std::string::npos) << m;
  EXPECT_EQ(m.find("hole"), std::string::npos) << m;
}

TEST(BranchRefusal, OnlyTheShortEdgesAreNamed)
{
  const std::string m = refusal(loopsOf({15.46, 21.29, 16.90}), 16.34, 5.2);
  EXPECT_NE(m.find("free edge 1 is 15.5 mm around"), std::string::npos) << m;
  EXPECT_EQ(m.find("free edge 2"), std::string::npos) << m;
  EXPECT_EQ(m.find("free edge 3"), std::string::npos) << m;
  EXPECT_NE(m.find("narrower than 4.9 mm"), std::string::npos) << m;
}

TEST(BranchRefusal, WideFreeEdgesLeaveAHoleOrANarrowNeck)
{
  const std::string m = refusal(loopsOf({300.0, 310.0, 40.0}), 16.34, 5.2);
  EXPECT_NE(m.find("3 free edges"), std::string::npos) << m;
  EXPECT_NE(m.find("hole in a wall"), std::string::npos) << m;
  EXPECT_NE(m.find("narrows below one bead ring (16.3 mm)"), std::string::npos) << m;
}

// The corpus's scanned bifurcation (centimetres), its slanted base levelled, under a 4.8 mm bead:
// every free edge is at least one ring around (15.1 mm), so the part splits, but one arm narrows
// below a ring between the junction and its edge and stays on the trunk. The refusal names that
// sub-part, not a hole.
TEST(BranchRefusal, ABranchNarrowingBetweenJunctionAndEdgeIsNamedOnItsSubPart)
{
  NullProgress progress;
  ParamSet unit;
  unit.set("unit", std::string("cm"));
  const ImportedPart part =
      importPart(builtinRegistry(), sourceDir() / "tests/data/real/junction_fine_cm.stl", &unit, progress);
  constexpr double kSubstrateZ = 406.961;
  LevelledBase levelled =
      levelBase(part.mesh, findPartTopology(part.report, part.mesh, kSubstrateZ, -1, true).lower);
  for (Vec3& v : levelled.mesh.vertices) v.z() += kSubstrateZ - levelled.cutZ;
  const MeshReport report = validateMesh(levelled.mesh);
  PlanRequest request(levelled.mesh, report);
  request.substrateZ = kSubstrateZ;
  request.params["process"].set("bead_width", 4.8);
  try {
    planPart(builtinRegistry(), request, progress);
    FAIL() << "planned a junction whose arm narrows below the bead";
  } catch (const InputError& e) {
    const std::string m = e.fullMessage();
    EXPECT_NE(m.find("sub-part 0 (trunk) of the multi-branch part keeps 3 free edges"), std::string::npos)
        << m;
    EXPECT_NE(m.find("narrows below one bead ring (15.1 mm)"), std::string::npos) << m;
    EXPECT_NE(m.find("--bead-width"), std::string::npos) << m;
    EXPECT_EQ(m.find("hole"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace spira::test
