#include "spira/field/harmonic_field.h"

#include <cmath>

#include <gtest/gtest.h>

#include "field/field_test_meshes.h"
#include "spira/base/error.h"

namespace spira {
namespace {

TEST(HarmonicField, TubeWithPlanarEdgesIsHeightOverH)
{
  const double r = 30.0, height = 45.0;
  const test::RingMesh tube = test::tubeMesh(r, height, r / 50.0);
  const std::vector<double> u = harmonicField(tube.mesh, tube.lower, tube.upper);
  ASSERT_EQ(u.size(), tube.mesh.vertices.size());
  double worst = 0.0;
  for (size_t v = 0; v < u.size(); ++v)
    worst = std::max(worst, std::abs(u[v] - tube.mesh.vertices[v].z() / height));
  EXPECT_LT(worst, 1e-6);
}

// A cone is flat once unrolled, and the unrolled sector's harmonic function with constant values
// on its two arcs is logarithmic in the distance to the apex, which is proportional to the radius:
// u = ln(r / r0) / ln(r1 / r0).
TEST(HarmonicField, ConeIsLogarithmicInRadius)
{
  const double r0 = 40.0, r1 = 15.0, height = 40.0;
  const test::RingMesh cone = test::coneMesh(r0, r1, height, r0 / 50.0);
  const std::vector<double> u = harmonicField(cone.mesh, cone.lower, cone.upper);
  double worst = 0.0;
  for (size_t v = 0; v < u.size(); ++v) {
    const double radius = cone.mesh.vertices[v].head<2>().norm();
    worst = std::max(worst, std::abs(u[v] - std::log(radius / r0) / std::log(r1 / r0)));
  }
  EXPECT_LT(worst, 1e-4);  // measured 1.6e-5 at edge r0 / 50
  // Not simply z / H: the field is curved along the slant.
  double offLinear = 0.0;
  for (size_t v = 0; v < u.size(); ++v)
    offLinear = std::max(offLinear, std::abs(u[v] - cone.mesh.vertices[v].z() / height));
  EXPECT_GT(offLinear, 0.05);
}

TEST(HarmonicField, FollowsATiltedUpperEdge)
{
  // Tube cut by a tilted plane at the top: the iso-lines follow the top edge, and the field stays
  // within [0, 1] with the boundary values held exactly.
  test::RingMesh tube = test::tubeMesh(10.0, 20.0, 0.5);
  for (Vec3& p : tube.mesh.vertices) p.z() *= 1.0 + 0.3 * (p.x() / 10.0) * (p.z() / 20.0);
  const std::vector<double> u = harmonicField(tube.mesh, tube.lower, tube.upper);
  for (int v : tube.lower) EXPECT_NEAR(u[v], 0.0, 1e-12);
  for (int v : tube.upper) EXPECT_NEAR(u[v], 1.0, 1e-12);
  for (double x : u) {
    EXPECT_GE(x, -1e-9);
    EXPECT_LE(x, 1.0 + 1e-9);
  }
}

TEST(HarmonicField, RejectsBadBoundarySets)
{
  const test::RingMesh tube = test::tubeMesh(5.0, 5.0, 1.0);
  EXPECT_THROW(harmonicField(tube.mesh, {}, tube.upper), InputError);
  EXPECT_THROW(harmonicField(tube.mesh, tube.lower, {}), InputError);
  EXPECT_THROW(harmonicField(tube.mesh, tube.lower, {int(tube.mesh.vertices.size())}), InputError);
  EXPECT_THROW(harmonicField(tube.mesh, tube.lower, {tube.lower[0]}), InputError);
}

TEST(HarmonicField, PartTouchingNoBoundaryIsNaN)
{
  test::RingMesh tube = test::tubeMesh(5.0, 5.0, 1.0);
  const int n = int(tube.mesh.vertices.size());
  tube.mesh.vertices.emplace_back(100, 0, 0);
  tube.mesh.vertices.emplace_back(101, 0, 0);
  tube.mesh.vertices.emplace_back(100, 1, 0);
  tube.mesh.faces.push_back({n, n + 1, n + 2});
  const std::vector<double> u = harmonicField(tube.mesh, tube.lower, tube.upper);
  for (int v = 0; v < n; ++v) EXPECT_TRUE(std::isfinite(u[v]));
  for (int v = n; v < n + 3; ++v) EXPECT_TRUE(std::isnan(u[v]));
}

}  // namespace
}  // namespace spira
