#include <gtest/gtest.h>

#include <cmath>

#include "planning/y_tube.h"
#include "planning/y_tube_geodesic.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/contour/branch_levels.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/branch_split.h"

namespace spira::test {
namespace {

const TriangleMesh& yMesh()
{
  static const TriangleMesh m = YTube().mesh();
  return m;
}

std::vector<double> heights(const TriangleMesh& m)
{
  std::vector<double> z(m.vertexCount());
  for (size_t v = 0; v < z.size(); ++v) z[v] = m.vertices[v].z();
  return z;
}

BranchSplitOptions beadOptions()
{
  BranchSplitOptions o;
  o.minPerimeter = kPi * 5.2;  // loops narrower than the bead are not branches
  return o;
}

Vec3 centroid(const TriangleMesh& m)
{
  Vec3 c = Vec3::Zero();
  double area = 0.0;
  for (size_t f = 0; f < m.faceCount(); ++f) {
    const double a = m.faceArea(f);
    const Face& fc = m.faces[f];
    c += a * (m.vertices[fc[0]] + m.vertices[fc[1]] + m.vertices[fc[2]]) / 3.0;
    area += a;
  }
  return c / area;
}

TEST(YTube, IsOneOpenManifoldWallWithThreeFreeEdges)
{
  const MeshReport r = validateMesh(yMesh());
  EXPECT_TRUE(r.isPlannable()) << r.toText();
  EXPECT_EQ(r.componentCount, 1u);
  ASSERT_EQ(r.boundaryLoops.size(), 3u);
  EXPECT_NEAR(r.boundaryLoops[0].zMin, 0.0, 1e-9);
  EXPECT_NEAR(r.boundaryLoops[0].zMax, 0.0, 1e-9);
  for (size_t k : {1, 2}) {
    EXPECT_NEAR(r.boundaryLoops[k].zMin, YTube().top, 1e-9);
    EXPECT_NEAR(r.boundaryLoops[k].zMax, YTube().top, 1e-9);
  }
  for (const auto& loop : r.boundaryLoops) EXPECT_NEAR(loop.length, 2 * kPi * 12.0, 0.01 * 2 * kPi * 12.0);
}

// The height function's saddle on the union of capsules is the crotch's top, in closed form.
TEST(BranchLevels, HeightOnTheYSplitsIntoTwoAtTheCrotch)
{
  const TriangleMesh& m = yMesh();
  NullProgress progress;
  BranchScanOptions scan;
  scan.minPerimeter = kPi * 5.2;
  const BranchSplit s = findFirstBranchSplit(m, heights(m), 0.0, scan, progress);
  ASSERT_TRUE(s.found);
  EXPECT_EQ(s.branches, 2u);
  EXPECT_LT(s.above - s.below, 1e-6);
  EXPECT_NEAR(s.saddle, YTube().saddle().z(), 1.2);  // one grid cell
  ASSERT_GE(s.saddleVertex, 0);
  EXPECT_NEAR(m.vertices[static_cast<size_t>(s.saddleVertex)].z(), s.saddle, 1e-6);
  EXPECT_LT((s.position - YTube().saddle()).norm(), 1.5);
  EXPECT_EQ(significantContourCount(extractIsoContour(m, heights(m), s.below - 1e-3), scan.minPerimeter), 1u);
  EXPECT_EQ(significantContourCount(extractIsoContour(m, heights(m), s.above + 1e-3), scan.minPerimeter), 2u);
}

TEST(BranchLevels, ABentTubeDoesNotBranch)
{
  YTube y;
  y.bothArms = false;
  const TriangleMesh m = y.mesh();
  NullProgress progress;
  BranchScanOptions scan;
  scan.minPerimeter = kPi * 5.2;
  const BranchSplit s = findFirstBranchSplit(m, heights(m), 0.0, scan, progress);
  EXPECT_FALSE(s.found);
  EXPECT_TRUE(s.vanished);  // the contours ran into the top edge
}

TEST(BranchSplit, YTubeSplitsIntoTrunkAndTwoArmsAtTheCrotch)
{
  const TriangleMesh& m = yMesh();
  const MeshReport r = validateMesh(m);
  NullProgress progress;
  const BranchDecomposition d =
      splitIntoMonoBranches(m, r.boundaryLoops[0].vertices, nullptr, beadOptions(), progress);
  ASSERT_EQ(d.saddles.size(), 1u);
  ASSERT_EQ(d.pieces.size(), 3u);
  EXPECT_FALSE(d.depthLimited);
  const BranchSaddle& s = d.saddles[0];
  const YTube y;
  // The saddle's geodesic distance from the base against the unrolled shortest path (0.3 % here)
  // and its place against the crotch's top (the mesh cuts the crease's corner by about 1 mm).
  const double exact = yTubeSaddleDistance(y);
  EXPECT_NEAR(s.level, exact, 0.01 * exact);
  EXPECT_LT((s.position - y.saddle()).norm(), 1.5);
  EXPECT_EQ(s.branches, 2u);
  EXPECT_EQ(s.piece, 0);
  EXPECT_NEAR(s.branchBase - s.trunkTop, d.junctionGap, 1e-9);
  EXPECT_NEAR(d.junctionGap, 0.5 * 1.8, 1e-9);  // half the thinnest deposit
  for (size_t k : {1, 2}) EXPECT_NEAR(d.pieces[k].supportGap, d.junctionGap, 1e-9);
  EXPECT_EQ(d.pieces[0].supportGap, 0.0);

  // Trunk first, standing on the substrate; the arms on it, left (x < 0) then right.
  const BranchPiece& trunk = d.pieces[0];
  EXPECT_TRUE(trunk.trunk);
  EXPECT_EQ(trunk.parent, -1);
  EXPECT_NEAR(trunk.report.boundaryLoops[static_cast<size_t>(trunk.lowerLoop)].zMax, 0.0, 1e-9);
  for (size_t k : {1, 2}) {
    const BranchPiece& arm = d.pieces[k];
    EXPECT_FALSE(arm.trunk);
    EXPECT_EQ(arm.parent, 0);
    EXPECT_EQ(arm.depth, 1);
    EXPECT_EQ(centroid(arm.mesh).x() > 0, k == 2);
    // Its other edge is the arm's open end at the top of the grid.
    const auto& upper = arm.report.boundaryLoops[static_cast<size_t>(1 - arm.lowerLoop)];
    EXPECT_NEAR(upper.zMin, y.top, 1e-9);
    // It starts above the trunk's top edge, within the gap (raw vs smoothed field: 1 mm).
    EXPECT_GT(arm.lowerLevel, s.trunkTop);
    EXPECT_LT(arm.lowerLevel, s.branchBase + 1.0);
  }
  double area = 0.0;
  for (const BranchPiece& p : d.pieces) {
    const MeshReport pr = validateMesh(p.mesh);
    EXPECT_TRUE(pr.isPlannable()) << pr.toText();
    EXPECT_EQ(pr.componentCount, 1u);
    EXPECT_EQ(pr.boundaryLoops.size(), 2u);
    EXPECT_EQ(pr.issueCount(MeshIssueKind::DegenerateFace), 0u);
    for (const auto& loop : pr.boundaryLoops) EXPECT_TRUE(loop.closed);
    area += pr.area;
  }
  // The pieces and the gap tile the part. The gap is a band of geodesic height g between the
  // trunk's top edge and the arms' lower edges: about g times the mean of their lengths.
  EXPECT_NEAR(area + d.gapArea, r.area, 1e-9 * r.area);
  const double trunkTop = trunk.report.boundaryLoops[static_cast<size_t>(1 - trunk.lowerLoop)].length;
  double armBottoms = 0.0;
  for (size_t k : {1, 2})
    armBottoms += d.pieces[k].report.boundaryLoops[static_cast<size_t>(d.pieces[k].lowerLoop)].length;
  EXPECT_NEAR(d.gapArea, 0.5 * (trunkTop + armBottoms) * d.junctionGap, 0.15 * d.gapArea);
  std::printf(
      "Y: saddle %.3f mm (exact %.3f) at (%.2f %.2f %.2f), %d bisections; gap %.2f mm, %.1f mm2 of %.1f\n",
      s.level, exact, s.position.x(), s.position.y(), s.position.z(), s.bisections, d.junctionGap, d.gapArea,
      r.area);
}

TEST(BranchSplit, ClosedArmsBecomeClosedBranches)
{
  YTube y;
  y.armRise = 30.0;
  y.top = 120.0;
  const TriangleMesh m = y.mesh();
  const MeshReport r = validateMesh(m);
  ASSERT_EQ(r.boundaryLoops.size(), 1u);
  NullProgress progress;
  const BranchDecomposition d =
      splitIntoMonoBranches(m, r.boundaryLoops[0].vertices, nullptr, beadOptions(), progress);
  ASSERT_EQ(d.pieces.size(), 3u);
  EXPECT_EQ(d.pieces[0].report.boundaryLoops.size(), 2u);
  EXPECT_EQ(d.pieces[1].report.boundaryLoops.size(), 1u);
  EXPECT_EQ(d.pieces[2].report.boundaryLoops.size(), 1u);
  EXPECT_NEAR(d.saddles[0].level, yTubeSaddleDistance(y), 0.01 * yTubeSaddleDistance(y));
}

TEST(BranchSplit, AMonoBranchPartStaysWhole)
{
  YTube y;
  y.bothArms = false;
  const TriangleMesh m = y.mesh();
  const MeshReport r = validateMesh(m);
  NullProgress progress;
  const BranchDecomposition d =
      splitIntoMonoBranches(m, r.boundaryLoops[0].vertices, nullptr, beadOptions(), progress);
  EXPECT_TRUE(d.saddles.empty());
  ASSERT_EQ(d.pieces.size(), 1u);
  EXPECT_EQ(d.pieces[0].mesh.faceCount(), m.faceCount());
  EXPECT_NEAR(d.pieces[0].area, r.area, 1e-9 * r.area);
}

// A tree: the right arm splits again. The split recurses from the right arm's own base: five
// mono-branch pieces, each after the one it stands on.
TEST(BranchSplit, AnArmThatSplitsAgainIsSplitFromItsOwnBase)
{
  const double r = 8.0;
  const Vec3 o(0, 0, 30), left(-20, 0, 55), right(18, 0, 50), fork(18, 0, 80), a(8, 0, 100), b(28, 0, 100);
  const Vec3 up(0, 0, 500);
  auto tree = [&](const Vec3& p) {
    double d = segmentDistance(p, Vec3(0, 0, -100), o);
    for (const auto& [s, e] : {std::pair<Vec3, Vec3>{o, left},
                               {left, left + up},
                               {o, right},
                               {right, fork},
                               {fork, a},
                               {a, a + up},
                               {fork, b},
                               {b, b + up}})
      d = std::min(d, segmentDistance(p, s, e));
    return d - r;
  };
  const TriangleMesh m = marchingTetrahedra(tree, Vec3(-32, -12, 0), 72, 24, 130, 1.0, 1.0);
  const MeshReport rep = validateMesh(m);
  ASSERT_TRUE(rep.isPlannable());
  ASSERT_EQ(rep.boundaryLoops.size(), 4u);
  NullProgress progress;
  const BranchDecomposition d =
      splitIntoMonoBranches(m, rep.boundaryLoops[0].vertices, nullptr, beadOptions(), progress);
  ASSERT_EQ(d.saddles.size(), 2u);
  ASSERT_EQ(d.pieces.size(), 5u);
  // Build order: trunk; left arm; the right arm up to its fork; its two sub-arms.
  EXPECT_EQ(d.pieces[0].parent, -1);
  EXPECT_LT(centroid(d.pieces[1].mesh).x(), -10.0);
  EXPECT_EQ(d.pieces[1].parent, 0);
  EXPECT_TRUE(d.pieces[2].trunk);
  EXPECT_EQ(d.pieces[2].parent, 0);
  EXPECT_EQ(d.saddles[1].piece, 2);
  for (size_t k : {3, 4}) {
    EXPECT_EQ(d.pieces[k].parent, 2);
    EXPECT_EQ(d.pieces[k].depth, 2);
    EXPECT_EQ(centroid(d.pieces[k].mesh).x() > 18.0, k == 4);
  }
  // The second saddle is the fork's crotch, measured from the right arm's own base.
  EXPECT_NEAR(d.saddles[1].position.x(), 18.0, 1.5);
  EXPECT_GT(d.saddles[1].position.z(), fork.z());
  double area = d.gapArea;
  for (const BranchPiece& p : d.pieces) {
    EXPECT_TRUE(p.report.isPlannable());
    EXPECT_EQ(p.report.componentCount, 1u);
    EXPECT_EQ(p.report.boundaryLoops.size(), 2u);
    area += p.area;
  }
  EXPECT_NEAR(area, rep.area, 1e-9 * rep.area);
}

// Arms that part and join again: a hole through the wall, not a tree of branches.
TEST(BranchSplit, ArmsThatJoinAgainAreRefused)
{
  const double r = 8.0;
  const Vec3 o(0, 0, 25), left(-20, 0, 45), right(20, 0, 45), join(0, 0, 65);
  auto ring = [&](const Vec3& p) {
    double d = segmentDistance(p, Vec3(0, 0, -100), o);
    for (const auto& [a, b] : {std::pair<Vec3, Vec3>{o, left}, {left, join}, {o, right}, {right, join}})
      d = std::min(d, segmentDistance(p, a, b));
    d = std::min(d, segmentDistance(p, join, Vec3(0, 0, 200)));
    return d - r;
  };
  const double cell = 1.0;
  const TriangleMesh m = marchingTetrahedra(ring, Vec3(-32, -12, 0), 64, 24, 90, cell, 1.0);
  const MeshReport rep = validateMesh(m);
  ASSERT_TRUE(rep.isPlannable());
  ASSERT_EQ(rep.boundaryLoops.size(), 2u);
  NullProgress progress;
  try {
    splitIntoMonoBranches(m, rep.boundaryLoops[0].vertices, nullptr, beadOptions(), progress);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("join again"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spira::test
