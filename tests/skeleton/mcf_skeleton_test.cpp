#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include "implicit_surface.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/skeleton/mcf_skeleton.h"

namespace spira {
namespace {

double distanceToZAxis(const Vec3& p)
{
  return std::hypot(p.x(), p.y());
}

void expectChainAlongZAxis(const SkeletonResult& r, double radius, double height)
{
  const CurveSkeleton& s = r.skeleton;
  EXPECT_TRUE(r.converged);
  ASSERT_EQ(s.branchCount(), 1u);
  EXPECT_TRUE(s.branchPoints.empty());
  EXPECT_EQ(s.loops, 0u);
  EXPECT_TRUE(s.monoBranch());
  EXPECT_TRUE(s.monotoneInZ);
  const Polyline& chain = s.branches[0];
  EXPECT_GE(chain.size(), 5u);
  for (const Vec3& p : chain) EXPECT_LT(distanceToZAxis(p), 0.02 * radius) << p.transpose();
  // The chain spans the tube's middle: it stops short of the (capped) ends by no more than the radius.
  EXPECT_LT(chain.front().z(), radius);
  EXPECT_GT(chain.back().z(), height - radius);
  for (size_t i = 1; i < chain.size(); ++i) EXPECT_GE(chain[i].z(), chain[i - 1].z() - 0.005 * height);
}

TEST(McfSkeleton, AnOpenCylinderIsOneChainAlongItsAxis)
{
  const double R = 15, H = 80;
  const TriangleMesh tube = makeOpenCylinder(R, H, 96, 40);
  NullProgress progress;
  const SkeletonResult r = computeCurveSkeleton(tube, SkeletonOptions{}, progress);
  EXPECT_EQ(r.capsAdded, 2u);
  expectChainAlongZAxis(r, R, H);
}

TEST(McfSkeleton, AClosedCylinderIsOneChainAlongItsAxis)
{
  const double R = 12, H = 70;
  std::vector<Eigen::Vector2d> profile{{0, 0}};
  for (int i = 0; i <= 35; ++i) profile.emplace_back(R, H * i / 35.0);
  profile.emplace_back(0, H);
  const TriangleMesh can = makeRevolved(profile, 72);
  ASSERT_EQ(validateMesh(can).boundaryLoops.size(), 0u);
  NullProgress progress;
  const SkeletonResult r = computeCurveSkeleton(can, SkeletonOptions{}, progress);
  EXPECT_EQ(r.capsAdded, 0u);
  expectChainAlongZAxis(r, R, H);
}

TEST(McfSkeleton, AnInclinedTubeGivesAStraightInclinedChain)
{
  // The open cylinder sheared by x += z tan(20 deg): its axis runs through (z tan 20, 0, z).
  const double R = 10, H = 60, slope = std::tan(degToRad(20));
  TriangleMesh tube = makeOpenCylinder(R, H, 80, 30);
  for (Vec3& v : tube.vertices) v.x() += slope * v.z();
  NullProgress progress;
  const SkeletonResult r = computeCurveSkeleton(tube, SkeletonOptions{}, progress);
  ASSERT_EQ(r.skeleton.branchCount(), 1u);
  EXPECT_TRUE(r.skeleton.monotoneInZ);
  for (const Vec3& p : r.skeleton.branches[0]) EXPECT_LT(std::hypot(p.x() - slope * p.z(), p.y()), 0.03 * R);
}

// The flow collapses its short edges in a fixed order, so the skeleton is the same to the bit on
// every run: computed again after the heap has changed, and on another thread (which allocates
// from another malloc arena), it has the same nodes and edges.
TEST(McfSkeleton, IsTheSameOnEveryRun)
{
  const TriangleMesh cone = makeOpenCone(35, 25, 60, 96, 40);
  const auto skeleton = [&] {
    NullProgress progress;
    return computeCurveSkeleton(cone, SkeletonOptions{}, progress).skeleton.graph;
  };
  const SkeletonGraph first = skeleton();
  std::vector<std::vector<double>> clutter;
  for (size_t k = 1; k < 3000; k += 7) clutter.emplace_back(k % 97 + 1, 1.0);
  const SkeletonGraph second = skeleton();
  SkeletonGraph third;
  std::thread([&] { third = skeleton(); }).join();
  const SkeletonGraph* const again[] = {&second, &third};
  for (const SkeletonGraph* run : again) {
    EXPECT_EQ(run->edges, first.edges);
    ASSERT_EQ(run->nodes.size(), first.nodes.size());
    for (size_t n = 0; n < first.nodes.size(); ++n)
      EXPECT_TRUE(run->nodes[n] == first.nodes[n])
          << "node " << n << ": " << run->nodes[n].transpose() << " vs " << first.nodes[n].transpose();
  }
}

TEST(McfSkeleton, AClosedYTubeHasThreeBranchesMeetingAtOnePoint)
{
  const double L = 40, r = 6, angle = degToRad(40);
  BoundingBox box;
  box.extend(Vec3(-L - 2 * r, -2 * r, -L - 2 * r));
  box.extend(Vec3(L + 2 * r, 2 * r, L + 2 * r));
  const TriangleMesh y =
      test::meshImplicit([&](const Vec3& p) { return test::yShape(p, L, r, angle); }, box, 1.6);
  const MeshReport report = validateMesh(y);
  ASSERT_TRUE(report.isPlannable()) << report.toText();
  ASSERT_EQ(report.componentCount, 1u);
  ASSERT_TRUE(report.boundaryLoops.empty());
  NullProgress progress;
  const SkeletonResult res = computeCurveSkeleton(y, SkeletonOptions{}, progress);
  const CurveSkeleton& s = res.skeleton;
  EXPECT_EQ(s.branchCount(), 3u);
  ASSERT_EQ(s.branchPoints.size(), 1u);
  EXPECT_EQ(s.endPoints.size(), 3u);
  EXPECT_EQ(s.loops, 0u);
  EXPECT_FALSE(s.monoBranch());
  EXPECT_FALSE(s.monotoneInZ);
  // The junction is near the origin, within the tube's radius.
  EXPECT_LT(s.branchPoints[0].norm(), r);
  // One branch goes down the trunk, one up each arm, each reaching most of the way to its tip.
  int down = 0, left = 0, right = 0;
  for (const Polyline& b : s.branches) {
    const Vec3& tip = b.back();
    EXPECT_GT((tip - b.front()).norm(), 0.6 * L);
    if (tip.z() < -0.5 * L) ++down;
    if (tip.z() > 0.4 * L && tip.x() < 0) ++left;
    if (tip.z() > 0.4 * L && tip.x() > 0) ++right;
  }
  EXPECT_EQ(down, 1);
  EXPECT_EQ(left, 1);
  EXPECT_EQ(right, 1);
}

TEST(McfSkeleton, AnOpenYTubeIsCappedAndKeepsItsThreeBranches)
{
  const double L = 40, r = 6, angle = degToRad(40);
  BoundingBox box;
  box.extend(Vec3(-L - 2 * r, -2 * r, -L - 2 * r));
  box.extend(Vec3(L + 2 * r, 2 * r, L + 2 * r));
  const TriangleMesh closed =
      test::meshImplicit([&](const Vec3& p) { return test::yShape(p, L, r, angle); }, box, 1.6);
  // Cut the three rounded ends off: drop every face with a vertex beyond 0.85 L along its limb.
  const Vec3 dirs[3] = {Vec3(0, 0, -1), Vec3(-std::sin(angle), 0, std::cos(angle)),
                        Vec3(std::sin(angle), 0, std::cos(angle))};
  TriangleMesh open;
  open.vertices = closed.vertices;
  for (const Face& f : closed.faces) {
    bool keep = true;
    for (int k : f)
      for (const Vec3& d : dirs) keep = keep && closed.vertices[k].dot(d) < 0.85 * L;
    if (keep) open.faces.push_back(f);
  }
  const MeshReport report = validateMesh(open);
  ASSERT_EQ(report.boundaryLoops.size(), 3u) << report.toText();
  ASSERT_TRUE(report.isPlannable()) << report.toText();
  NullProgress progress;
  const SkeletonResult res = computeCurveSkeleton(open, SkeletonOptions{}, progress);
  EXPECT_EQ(res.capsAdded, 3u);
  EXPECT_EQ(res.skeleton.branchCount(), 3u);
  EXPECT_EQ(res.skeleton.branchPoints.size(), 1u);
  EXPECT_EQ(res.skeleton.loops, 0u);
}

TEST(McfSkeleton, RefusesMeshesItCannotContract)
{
  NullProgress progress;
  EXPECT_THROW(computeCurveSkeleton(TriangleMesh{}, SkeletonOptions{}, progress), InputError);
  // Two separate tubes.
  TriangleMesh two = makeOpenCylinder(5, 20, 24, 4);
  const TriangleMesh other = makeOpenCylinder(5, 20, 24, 4);
  const int offset = static_cast<int>(two.vertices.size());
  for (Vec3 v : other.vertices) two.vertices.push_back(v + Vec3(30, 0, 0));
  for (Face f : other.faces) two.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  try {
    computeCurveSkeleton(two, SkeletonOptions{}, progress);
    FAIL() << "two pieces accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("2 separate pieces"), std::string::npos) << e.what();
    EXPECT_FALSE(e.hint().empty());
  }
  SkeletonOptions none;
  none.maxIterations = 0;
  EXPECT_THROW(computeCurveSkeleton(makeOpenCylinder(5, 20, 24, 4), none, progress), InputError);
}

TEST(McfSkeleton, StopsAtTheIterationLimitWithAWarningAndHonoursCancel)
{
  const TriangleMesh tube = makeOpenCylinder(15, 80, 96, 40);
  SkeletonOptions one;
  one.maxIterations = 1;
  NullProgress progress;
  const SkeletonResult r = computeCurveSkeleton(tube, one, progress);
  EXPECT_EQ(r.iterations, 1u);
  EXPECT_FALSE(r.converged);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("limit of 1 steps"), std::string::npos) << r.warnings[0];

  CallbackProgress cancelled;
  cancelled.cancel();
  EXPECT_THROW(computeCurveSkeleton(tube, SkeletonOptions{}, cancelled), Cancelled);
}

}  // namespace
}  // namespace spira
