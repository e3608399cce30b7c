#include <cmath>

#include <gtest/gtest.h>

#include "mesh/mesh_test_shapes.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/triangle_mesh.h"

using namespace spira;

namespace {

TriangleMesh unitSquare()
{
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

}  // namespace

TEST(TriangleMesh, BoundsOfCylinderAreExact)
{
  const TriangleMesh m = makeOpenCylinder(25.0, 40.0, 64, 8);
  const BoundingBox b = m.bounds();
  EXPECT_EQ(b.min, Vec3(-25.0, -25.0, 0.0));
  EXPECT_EQ(b.max, Vec3(25.0, 25.0, 40.0));
  EXPECT_NEAR(b.diagonal(), std::sqrt(50.0 * 50.0 * 2 + 40.0 * 40.0), 1e-12);
  EXPECT_EQ(b.center(), Vec3(0.0, 0.0, 20.0));
}

TEST(TriangleMesh, BoundsSkipNonFiniteVerticesAndEmptyIsEmpty)
{
  TriangleMesh m = unitSquare();
  m.vertices.push_back(Vec3(std::nan(""), 5.0, 5.0));
  m.vertices.push_back(Vec3(1.0, INFINITY, 2.0));
  const BoundingBox b = m.bounds();
  EXPECT_EQ(b.min, Vec3(0, 0, 0));
  EXPECT_EQ(b.max, Vec3(1, 1, 0));
  EXPECT_TRUE(TriangleMesh().bounds().empty());
  EXPECT_EQ(TriangleMesh().bounds().size(), Vec3::Zero());
}

TEST(TriangleMesh, FaceNormalAndArea)
{
  const TriangleMesh m = unitSquare();
  EXPECT_EQ(m.faceNormalScaled(0), Vec3(0, 0, 1));
  EXPECT_EQ(m.faceNormal(1), Vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(m.faceArea(0), 0.5);
  EXPECT_DOUBLE_EQ(m.area(), 1.0);
  TriangleMesh flat = m;
  flat.vertices[2] = Vec3(2, 0, 0);  // face 0 collinear
  EXPECT_EQ(flat.faceNormal(0), Vec3::Zero());
}

TEST(TriangleMesh, FacetedCylinderAreaMatchesPolygonPrism)
{
  const int n = 48;
  const double r = 12.5, h = 30.0;
  const TriangleMesh m = makeOpenCylinder(r, h, n, 7);
  const double expected = n * h * 2.0 * r * std::sin(kPi / n);  // n flat rectangles
  EXPECT_NEAR(m.area(), expected, 1e-10 * expected);
}

TEST(TriangleMesh, MeanEdgeLengthCountsEachEdgeOnce)
{
  // Edges: four sides of length 1 and one diagonal of sqrt(2); the diagonal is shared.
  EXPECT_DOUBLE_EQ(unitSquare().meanEdgeLength(), (4.0 + std::sqrt(2.0)) / 5.0);
  const TriangleMesh t = makeTetrahedron(3.0);
  EXPECT_NEAR(t.meanEdgeLength(), 3.0, 1e-12);
  EXPECT_EQ(TriangleMesh().meanEdgeLength(), 0.0);
}

TEST(TriangleMesh, VertexNormalsAreRadialOnCylinderAndZeroWhenIsolated)
{
  TriangleMesh m = makeOpenCylinder(10.0, 10.0, 32, 4);
  m.vertices.push_back(Vec3(100, 0, 0));  // used by no face
  const std::vector<Vec3> n = m.vertexNormals();
  ASSERT_EQ(n.size(), m.vertexCount());
  for (size_t v = 32; v < 32 * 4; ++v) {  // interior rings: the ring's neighbours are symmetric
    const Vec3 radial = Vec3(m.vertices[v].x(), m.vertices[v].y(), 0.0).normalized();
    EXPECT_NEAR(n[v].norm(), 1.0, 1e-12);
    EXPECT_GT(n[v].dot(radial), std::cos(kPi / 32));
    EXPECT_NEAR(n[v].z(), 0.0, 1e-12);
  }
  EXPECT_EQ(n.back(), Vec3::Zero());
}

TEST(TriangleMesh, TransformMovesVerticesAndKeepsAreaAndOrientation)
{
  const TriangleMesh t = makeTetrahedron(10.0);
  const Transform T = transformFromXyzZyx(Vec3(5, -3, 7), 0.3, -0.2, 1.1);
  const TriangleMesh moved = t.transformed(T);
  EXPECT_NEAR(moved.area(), t.area(), 1e-10);
  EXPECT_NEAR(test::signedVolume(moved), test::signedVolume(t), 1e-10);
  for (size_t v = 0; v < t.vertexCount(); ++v)
    EXPECT_TRUE(moved.vertices[v].isApprox(T * t.vertices[v], 1e-14));
  EXPECT_EQ(moved.faces, t.faces);

  // A mirror keeps faces pointing outwards by reversing them.
  Transform mirror = Transform::Identity();
  mirror.linear() = Vec3(-1, 1, 1).asDiagonal();
  TriangleMesh m = t;
  m.transform(mirror);
  EXPECT_GT(test::signedVolume(m), 0.0);
  EXPECT_NEAR(test::signedVolume(m), test::signedVolume(t), 1e-10);
}
