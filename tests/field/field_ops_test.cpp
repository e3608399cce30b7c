#include "spira/field/field_ops.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "field/field_test_meshes.h"
#include "spira/base/error.h"

namespace spira {
namespace {

// A linear function of position: P1 interpolation reproduces it exactly.
double linear(const Vec3& p)
{
  return 2.0 * p.x() - 3.0 * p.y() + 0.5 * p.z() + 7.0;
}

TEST(FieldOps, ArgmaxSkipsNonFiniteAndPrefersLowestId)
{
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(argmaxVertex({1.0, 5.0, inf, 5.0, std::nan("")}), 1);
  EXPECT_EQ(argmaxVertex({}), -1);
  EXPECT_EQ(argmaxVertex({inf, std::nan("")}), -1);
}

TEST(FieldOps, InterpolationIsExactForLinearFields)
{
  const test::RingMesh tube = test::tubeMesh(5.0, 4.0, 1.0);
  std::vector<double> values;
  for (const Vec3& p : tube.mesh.vertices) values.push_back(linear(p));
  const Vec3 w(0.2, 0.5, 0.3);
  for (int f : {0, 7, int(tube.mesh.faces.size()) - 1}) {
    const Face& t = tube.mesh.faces[f];
    const Vec3 p =
        w[0] * tube.mesh.vertices[t[0]] + w[1] * tube.mesh.vertices[t[1]] + w[2] * tube.mesh.vertices[t[2]];
    EXPECT_NEAR(interpolateField(tube.mesh, values, f, w), linear(p), 1e-12);
  }
  EXPECT_THROW(interpolateField(tube.mesh, values, int(tube.mesh.faces.size()), w), InputError);
  EXPECT_THROW(interpolateField(tube.mesh, {1.0}, 0, w), InputError);
}

TEST(FieldOps, GradientIsTheProjectedGradientOfALinearField)
{
  const test::RingMesh dome = test::domeMesh(10.0, 1.0);
  std::vector<double> values;
  for (const Vec3& p : dome.mesh.vertices) values.push_back(linear(p));
  const Vec3 g(2.0, -3.0, 0.5);
  const std::vector<Vec3> grads = faceGradients(dome.mesh, values);
  ASSERT_EQ(grads.size(), dome.mesh.faces.size());
  for (size_t f = 0; f < dome.mesh.faces.size(); f += 17) {
    const Face& t = dome.mesh.faces[f];
    const Vec3 n = (dome.mesh.vertices[t[1]] - dome.mesh.vertices[t[0]])
                       .cross(dome.mesh.vertices[t[2]] - dome.mesh.vertices[t[0]])
                       .normalized();
    const Vec3 expected = g - g.dot(n) * n;
    EXPECT_LT((grads[f] - expected).norm(), 1e-9);
    EXPECT_LT((faceGradient(dome.mesh, values, int(f)) - expected).norm(), 1e-9);
  }
}

TEST(FieldOps, GradientOfDegenerateFaceIsZero)
{
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  m.faces = {{0, 1, 2}};
  EXPECT_EQ(faceGradient(m, {0.0, 1.0, 2.0}, 0), Vec3::Zero());
}

}  // namespace
}  // namespace spira
