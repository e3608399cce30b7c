#include <gtest/gtest.h>

#include <string>

#include "spira/base/error.h"
#include "spira/planning/branch_refusal.h"

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

}  // namespace
}  // namespace spira::test
