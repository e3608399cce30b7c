// Rays cast into a mesh's bounding-volume tree hit what a brute-force cast over every triangle hits,
// including rays straight down a grid line (a zero direction component of either sign: 0 * inf in the
// slab test) and through vertices.
#include <gtest/gtest.h>

#include <cmath>

#include "spira/mesh/ray_bvh.h"
#include "spira/mesh/substrate_surface.h"

namespace spira {
namespace {

// A bowed plate meshed on a 1 mm grid from -80 to 80 mm.
TriangleMesh bowedPlate()
{
  TriangleMesh mesh;
  const int n = 161;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -80.0 + i, y = -80.0 + j;
      mesh.vertices.emplace_back(x, y, 0.3 * std::sin(x / 25.0) + 0.002 * y);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i;
      mesh.faces.push_back({a, a + 1, a + n + 1});
      mesh.faces.push_back({a, a + n + 1, a + n});
    }
  return mesh;
}

TEST(RayBvh, RaysDownGridLinesAndThroughVerticesHitThePlate)
{
  const TriangleMesh plate = bowedPlate();
  const RayBvh tree(plate);
  size_t rays = 0;
  for (const Vec3& down : {Vec3(0.0, 0.0, -1.0), Vec3(-0.0, -0.0, -1.0), Vec3(-Vec3(0.0, 0.0, 1.0))})
    for (double x = -70.0; x <= 70.0; x += 0.5)
      for (double y = -70.0; y <= 70.0; y += 0.5) {
        const RayHit hit = tree.firstHit(Vec3(x, y, 6.0), down, 0.0, 10.0);
        ASSERT_GE(hit.face, 0) << x << " " << y << " " << down.transpose();
        const double z = 0.3 * std::sin(x / 25.0) + 0.002 * y;
        // The plate between grid points is flat in each triangle: within the chord of the bow.
        EXPECT_NEAR(6.0 - hit.distance, z, 2e-4) << x << " " << y;
        ++rays;
      }
  EXPECT_EQ(rays, 3u * 281u * 281u);
  // A ray beside the plate, parallel to its edge, misses it.
  EXPECT_LT(tree.firstHit(Vec3(80.5, 0.0, 6.0), -Vec3(0.0, 0.0, 1.0), 0.0, 10.0).face, 0);
}

// The deposit check and the plan measure down to a substrate mesh this way: a point over a grid line.
TEST(SubstrateSurface, DepthBelowAPointOverAGridLine)
{
  const SubstrateSurface plate = SubstrateSurface::mesh(bowedPlate());
  const double z = 0.3 * std::sin(50.0 / 25.0);
  EXPECT_NEAR(plate.depthBelow(Vec3(50.0, 0.0, 1.8), Vec3(0.0, 0.0, 1.0), 4.4, 4.4), 1.8 - z, 1e-12);
  EXPECT_NEAR(plate.depthBelow(Vec3(10.0, 0.0, -0.2), Vec3(0.0, 0.0, 1.0), 4.4, 4.4),
              -0.2 - 0.3 * std::sin(10.0 / 25.0), 1e-12);
}

}  // namespace
}  // namespace spira
