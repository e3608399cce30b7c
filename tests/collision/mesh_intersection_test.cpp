#include <gtest/gtest.h>

#include <random>

#include "collision/mesh_builders.h"
#include "spira/base/units.h"
#include "spira/collision/basic_shapes.h"
#include "spira/collision/gjk.h"
#include "spira/collision/mesh_intersection.h"
#include "spira/collision/triangle_intersection.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira {
namespace {

TEST(TriangleIntersection, CrossingTouchingCoplanarAndApart)
{
  const Vec3 a0(0, 0, 0), a1(10, 0, 0), a2(0, 10, 0);
  // Crossing the plane inside the triangle.
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(2, 2, -3), Vec3(2, 2, 3), Vec3(8, -5, 0)));
  // Standing on it with one vertex (touching counts).
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(3, 3, 0), Vec3(3, 3, 5), Vec3(4, 1, 5)));
  // Crossing the plane outside the triangle.
  EXPECT_FALSE(trianglesIntersect(a0, a1, a2, Vec3(8, 8, -3), Vec3(8, 8, 3), Vec3(12, 12, 0)));
  // Coplanar overlap, coplanar containment, coplanar apart.
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(4, 4, 0), Vec3(14, 4, 0), Vec3(4, 14, 0)));
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(1, 2, 0)));
  EXPECT_FALSE(trianglesIntersect(a0, a1, a2, Vec3(6, 6, 0), Vec3(16, 6, 0), Vec3(6, 16, 0)));
  // Parallel planes 1 mm apart.
  EXPECT_FALSE(trianglesIntersect(a0, a1, a2, Vec3(0, 0, 1), Vec3(10, 0, 1), Vec3(0, 10, 1)));
}

TEST(TriangleIntersection, RandomPairsAgreeWithGjk)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  const auto rv = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  int both = 0, neither = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    const Vec3 a0 = rv(), a1 = rv(), a2 = rv();
    const Vec3 shift(u(rng), 0, 0);
    const Vec3 b0 = rv() + shift, b1 = rv() + shift, b2 = rv() + shift;
    const GjkResult g = gjkDistance(TriangleShape(a0, a1, a2), TriangleShape(b0, b1, b2));
    if (!g.intersecting && g.distance < 1e-7) continue;  // grazing: either answer is right
    const bool hit = trianglesIntersect(a0, a1, a2, b0, b1, b2);
    EXPECT_EQ(hit, g.intersecting) << "trial " << trial << " gjk distance " << g.distance;
    (hit ? both : neither) += 1;
  }
  EXPECT_GT(both, 500);
  EXPECT_GT(neither, 500);
}

using test::boxMesh;

TEST(MeshIntersection, ABoxAcrossACylinderWallIntersectsAndOneInsideDoesNot)
{
  const TriangleBvh wall(makeOpenCylinder(50.0, 100.0, 128, 20));
  const TriangleMesh link = boxMesh(Vec3(-5, -5, -5), Vec3(5, 5, 5));
  const TriangleBvh linkBvh(link);
  const auto at = [](double x, double z) {
    Transform T = Transform::Identity();
    T.translation() = Vec3(x, 0, z);
    return T;
  };
  const Transform I = Transform::Identity();
  // Straddling the wall at radius 50: crosses it.
  EXPECT_TRUE(meshesIntersect(linkBvh, at(50, 50), wall, I));
  EXPECT_TRUE(meshIntersects(link, at(50, 50), wall));
  // Wholly inside the tube (the nearest box corner at radius 35 + 5 sqrt 2 < 50 * cos(pi / 128)).
  EXPECT_FALSE(meshesIntersect(linkBvh, at(30, 50), wall, I));
  EXPECT_FALSE(meshIntersects(link, at(30, 50), wall));
  // Above the wall's top edge: 5 mm gap; within a 6 mm margin, not within 4 mm.
  EXPECT_FALSE(meshesIntersect(linkBvh, at(50, 110), wall, I));
  EXPECT_TRUE(meshesIntersect(linkBvh, at(50, 110), wall, I, 6.0));
  EXPECT_FALSE(meshesIntersect(linkBvh, at(50, 110), wall, I, 4.0));
  // The same placement expressed through two world transforms.
  const Transform T_world_b = transformFromXyzRpy(Vec3(100, -20, 3), Vec3(0.3, -0.2, 1.1));
  EXPECT_TRUE(meshesIntersect(linkBvh, T_world_b * at(50, 50), wall, T_world_b));
  EXPECT_FALSE(meshesIntersect(linkBvh, T_world_b * at(30, 50), wall, T_world_b));
}

TEST(MeshIntersection, RandomPlacementsEqualBruteForceOverAllFacePairs)
{
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const TriangleMesh part = makeOpenCylinder(50.0, 100.0, 48, 10);
  const TriangleMesh link = makeHemisphere(20.0, 16, 6);
  const TriangleBvh partBvh(part), linkBvh(link);
  int hits = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Transform T_part_link = transformFromXyzRpy(Vec3(60 * u(rng), 60 * u(rng), 50 + 60 * u(rng)),
                                                      Vec3(3 * u(rng), 3 * u(rng), 3 * u(rng)));
    const double margin = trial % 2 ? 3.0 : 0.0;
    std::vector<std::pair<size_t, size_t>> brute;
    for (size_t fa = 0; fa < link.faceCount(); ++fa) {
      const TriangleShape ta = linkBvh.triangle(fa);
      const TriangleShape carried(T_part_link * ta.vertex(0), T_part_link * ta.vertex(1),
                                  T_part_link * ta.vertex(2));
      for (size_t fb = 0; fb < part.faceCount(); ++fb) {
        const TriangleShape tb = partBvh.triangle(fb);
        const bool hit = margin > 0.0
                             ? gjkWithin(carried, tb, margin)
                             : trianglesIntersect(carried.vertex(0), carried.vertex(1), carried.vertex(2),
                                                  tb.vertex(0), tb.vertex(1), tb.vertex(2));
        if (hit) brute.emplace_back(fa, fb);
      }
    }
    hits += !brute.empty();
    const Transform I = Transform::Identity();
    EXPECT_EQ(meshesIntersect(linkBvh, T_part_link, partBvh, I, margin), !brute.empty()) << trial;
    EXPECT_EQ(meshIntersects(link, T_part_link, partBvh, margin), !brute.empty()) << trial;
    EXPECT_EQ(intersectingFaces(linkBvh, T_part_link, partBvh, I, margin), brute) << trial;
  }
  EXPECT_GT(hits, 5);
  EXPECT_LT(hits, 35);
}

}  // namespace
}  // namespace spira
