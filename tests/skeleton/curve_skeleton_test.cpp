#include <gtest/gtest.h>

#include "spira/skeleton/curve_skeleton.h"

namespace spira {
namespace {

SkeletonGraph chain(const std::vector<Vec3>& points)
{
  SkeletonGraph g;
  g.nodes = points;
  for (size_t i = 1; i < points.size(); ++i)
    g.edges.push_back({static_cast<int>(i - 1), static_cast<int>(i)});
  return g;
}

TEST(CurveSkeleton, AStraightRisingChainIsOneMonotoneBranch)
{
  // Listed top down and in scrambled edge order: the chain is read from its lower end.
  SkeletonGraph g;
  g.nodes = {Vec3(0, 0, 30), Vec3(0, 0, 0), Vec3(0, 0, 20), Vec3(0, 0, 10)};
  g.edges = {{0, 2}, {3, 1}, {2, 3}};
  const CurveSkeleton s = analyseSkeleton(g, 0.0);
  ASSERT_EQ(s.branchCount(), 1u);
  EXPECT_TRUE(s.branchPoints.empty());
  EXPECT_EQ(s.endPoints.size(), 2u);
  EXPECT_EQ(s.loops, 0u);
  EXPECT_EQ(s.components, 1u);
  EXPECT_TRUE(s.monoBranch());
  EXPECT_TRUE(s.monotoneInZ);
  const Polyline& b = s.branches[0];
  ASSERT_EQ(b.size(), 4u);
  for (size_t i = 0; i < b.size(); ++i) EXPECT_DOUBLE_EQ(b[i].z(), 10.0 * i);
}

TEST(CurveSkeleton, AChainThatFallsIsNotMonotoneBeyondTheTolerance)
{
  const SkeletonGraph g = chain({Vec3(0, 0, 0), Vec3(0, 0, 10), Vec3(1, 0, 9.5), Vec3(0, 0, 20)});
  EXPECT_FALSE(analyseSkeleton(g, 0.4).monotoneInZ);  // falls 0.5 mm
  EXPECT_TRUE(analyseSkeleton(g, 0.6).monotoneInZ);
  // A horizontal chain has no point per height.
  EXPECT_FALSE(analyseSkeleton(chain({Vec3(0, 0, 5), Vec3(10, 0, 5)}), 0.1).monotoneInZ);
}

TEST(CurveSkeleton, AYHasThreeBranchesAndOneBranchPoint)
{
  SkeletonGraph g;
  g.nodes = {Vec3(0, 0, 0),  Vec3(0, 0, -5), Vec3(0, 0, -10), Vec3(-3, 0, 4),
             Vec3(-6, 0, 8), Vec3(3, 0, 4),  Vec3(6, 0, 8)};
  g.edges = {{0, 1}, {1, 2}, {0, 3}, {3, 4}, {0, 5}, {5, 6}};
  const CurveSkeleton s = analyseSkeleton(g, 0.0);
  EXPECT_EQ(s.branchCount(), 3u);
  ASSERT_EQ(s.branchPoints.size(), 1u);
  EXPECT_EQ(s.branchPoints[0], Vec3::Zero());
  EXPECT_EQ(s.endPoints.size(), 3u);
  EXPECT_EQ(s.loops, 0u);
  EXPECT_FALSE(s.monoBranch());
  EXPECT_FALSE(s.monotoneInZ);
  for (const Polyline& b : s.branches) {
    EXPECT_EQ(b.size(), 3u);
    EXPECT_EQ(b.front(), Vec3::Zero());  // every branch starts at the branch point
  }
}

TEST(CurveSkeleton, LoopsAreCountedAndAPureCycleIsOneClosedBranch)
{
  SkeletonGraph ring = chain({Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)});
  ring.edges.push_back({3, 0});
  const CurveSkeleton s = analyseSkeleton(ring, 0.0);
  EXPECT_EQ(s.loops, 1u);
  ASSERT_EQ(s.branchCount(), 1u);
  EXPECT_EQ(s.branches[0].size(), 5u);
  EXPECT_EQ(s.branches[0].front(), s.branches[0].back());
  EXPECT_FALSE(s.monoBranch());

  // A ring with a tail: one branch point of degree 3, two branches (the tail and the ring).
  SkeletonGraph tailed = ring;
  tailed.nodes.push_back(Vec3(2, 0, 0));
  tailed.edges.push_back({0, 4});
  const CurveSkeleton t = analyseSkeleton(tailed, 0.0);
  EXPECT_EQ(t.loops, 1u);
  EXPECT_EQ(t.branchPoints.size(), 1u);
  EXPECT_EQ(t.branchCount(), 2u);
}

TEST(CurveSkeleton, DuplicateEdgesSelfLoopsAndPiecesAreHandled)
{
  SkeletonGraph g = chain({Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, 2)});
  g.edges.push_back({1, 0});  // duplicate, reversed
  g.edges.push_back({2, 2});  // self-loop
  const CurveSkeleton s = analyseSkeleton(g, 0.0);
  EXPECT_EQ(s.graph.edges.size(), 2u);
  EXPECT_EQ(s.loops, 0u);
  EXPECT_TRUE(s.monotoneInZ);

  SkeletonGraph two = chain({Vec3(0, 0, 0), Vec3(0, 0, 1)});
  two.nodes.push_back(Vec3(5, 0, 0));
  two.nodes.push_back(Vec3(5, 0, 1));
  two.edges.push_back({2, 3});
  const CurveSkeleton p = analyseSkeleton(two, 0.0);
  EXPECT_EQ(p.components, 2u);
  EXPECT_EQ(p.branchCount(), 2u);
  EXPECT_FALSE(p.monoBranch());
  EXPECT_FALSE(p.monotoneInZ);
}

}  // namespace
}  // namespace spira
