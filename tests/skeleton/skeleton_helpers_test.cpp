#include <cmath>

#include <gtest/gtest.h>

#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/skeleton/capped_surface.h"
#include "spira/skeleton/skeleton_centering.h"
#include "spira/skeleton/skeleton_pruning.h"

namespace spira {
namespace {

TEST(CappedSurface, CapsAnOpenTubeIntoAClosedConsistentSurface)
{
  const double R = 10, H = 30;
  const int segments = 40;
  const TriangleMesh tube = makeOpenCylinder(R, H, segments, 6);
  const MeshReport before = validateMesh(tube);
  ASSERT_EQ(before.boundaryLoops.size(), 2u);
  const CappedSurface capped = capBoundaryLoops(tube, before.boundaryLoops);
  EXPECT_EQ(capped.capsAdded, 2u);
  EXPECT_EQ(capped.mesh.vertexCount(), tube.vertexCount() + 2);
  EXPECT_EQ(capped.mesh.faceCount(), tube.faceCount() + 2 * segments);
  const MeshReport after = validateMesh(capped.mesh);
  EXPECT_EQ(after.partClass, PartClass::Unsupported);  // no free edge left
  EXPECT_TRUE(after.boundaryLoops.empty());
  EXPECT_TRUE(after.isPlannable()) << after.toText();
  EXPECT_FALSE(after.hasIssue(MeshIssueKind::InconsistentOrientation));
  // The caps are the two discs of the regular polygon: area n/2 R^2 sin(2 pi / n) each.
  const double disc = 0.5 * segments * R * R * std::sin(2 * kPi / segments);
  EXPECT_NEAR(capped.mesh.area() - tube.area(), 2 * disc, 1e-9 * disc);
  // Outward: the bottom cap faces -Z, the top one +Z.
  for (size_t f = tube.faceCount(); f < capped.mesh.faceCount(); ++f) {
    const Vec3 n = capped.mesh.faceNormal(f);
    const double z = capped.mesh.vertices[capped.mesh.faces[f][2]].z();
    EXPECT_NEAR(n.z(), z < H / 2 ? -1.0 : 1.0, 1e-12);
  }
}

TEST(SkeletonPruning, RemovesSpursShorterThanTheRadiusAndKeepsLimbs)
{
  const double R = 10;
  const TriangleMesh tube = makeOpenCylinder(R, 100, 64, 20);
  // The axis with a 4 mm spur at z = 20 and a 30 mm limb at z = 70 (longer than R).
  SkeletonGraph g;
  for (int k = 0; k <= 10; ++k) g.nodes.push_back(Vec3(0, 0, 10.0 * k));
  for (int k = 1; k <= 10; ++k) g.edges.push_back({k - 1, k});
  g.nodes.push_back(Vec3(4, 0, 20));
  g.edges.push_back({2, 11});
  g.nodes.push_back(Vec3(15, 0, 70));
  g.nodes.push_back(Vec3(30, 0, 70));
  g.edges.push_back({7, 12});
  g.edges.push_back({12, 13});
  EXPECT_NEAR(distanceToSurface(tube, Vec3(0, 0, 20)), R * std::cos(kPi / 64), 1e-9);
  EXPECT_EQ(pruneSpurs(g, tube), 1u);
  EXPECT_EQ(g.nodes.size(), 13u);
  const CurveSkeleton s = analyseSkeleton(g, 0.0);
  EXPECT_EQ(s.branchPoints.size(), 1u);
  ASSERT_EQ(s.branchCount(), 3u);
  EXPECT_DOUBLE_EQ(s.branchPoints[0].z(), 70.0);
}

TEST(SkeletonCentering, MovesChainNodesOntoTheAxisOfATube)
{
  const double R = 12;
  const TriangleMesh tube = makeOpenCylinder(R, 60, 96, 24);
  // A chain 1.5 mm off the axis, slightly tilted.
  SkeletonGraph g;
  for (int k = 0; k <= 8; ++k) g.nodes.push_back(Vec3(1.5, 0.2 * k, 10 + 5.0 * k));
  for (int k = 1; k <= 8; ++k) g.edges.push_back({k - 1, k});
  NullProgress progress;
  EXPECT_EQ(centreInCrossSections(g, tube, progress), 9u);
  for (const Vec3& p : g.nodes) EXPECT_LT(std::hypot(p.x(), p.y()), 0.02 * R) << p.transpose();
  // Near the rim the plane normal to a skeleton that bends sideways runs out through the free
  // edge; the horizontal section is used instead.
  SkeletonGraph bent;
  bent.nodes = {Vec3(1, 0, 58), Vec3(1, 40, 59)};
  bent.edges = {{0, 1}};
  EXPECT_EQ(centreInCrossSections(bent, tube, progress), 1u);
  EXPECT_LT(std::hypot(bent.nodes[0].x(), bent.nodes[0].y()), 0.02 * R);
  EXPECT_NEAR(bent.nodes[0].z(), 58.0, 1e-9);
  EXPECT_EQ(bent.nodes[1], Vec3(1, 40, 59));  // outside the tube: no section goes round it
  // A node outside the part has no section around it and stays.
  SkeletonGraph outside;
  outside.nodes = {Vec3(30, 0, 30), Vec3(30, 0, 40)};
  outside.edges = {{0, 1}};
  EXPECT_EQ(centreInCrossSections(outside, tube, progress), 0u);
  EXPECT_EQ(outside.nodes[0], Vec3(30, 0, 30));
}

}  // namespace
}  // namespace spira
