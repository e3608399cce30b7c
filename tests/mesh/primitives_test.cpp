#include <cmath>

#include <gtest/gtest.h>

#include "mesh/mesh_test_shapes.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"

using namespace spira;

namespace {

double radiusOf(const Vec3& p)
{
  return std::hypot(p.x(), p.y());
}

// Every face's normal points away from the axis (or up, for faces round a top pole).
void expectOutwardFromAxis(const TriangleMesh& m)
{
  for (size_t f = 0; f < m.faceCount(); ++f) {
    const Vec3 c = test::centroidOf(m, static_cast<int>(f));
    EXPECT_GT(m.faceNormal(f).dot(Vec3(c.x(), c.y(), 0.0)), 0.0) << "face " << f;
  }
}

void expectClean(const MeshReport& r)
{
  EXPECT_TRUE(r.issues.empty()) << r.toText();
  EXPECT_EQ(r.componentCount, 1u);
}

}  // namespace

TEST(Primitives, OpenCylinderIsExactAndOpen)
{
  const int n = 40, rings = 6;
  const TriangleMesh m = makeOpenCylinder(20.0, 50.0, n, rings);
  EXPECT_EQ(m.vertexCount(), static_cast<size_t>(n * (rings + 1)));
  EXPECT_EQ(m.faceCount(), static_cast<size_t>(2 * n * rings));
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    EXPECT_NEAR(radiusOf(m.vertices[v]), 20.0, 1e-13 * 20.0);
    EXPECT_DOUBLE_EQ(m.vertices[v].z(), 50.0 * static_cast<double>(v / n) / rings);
  }
  EXPECT_EQ(m.vertices[0], Vec3(20, 0, 0));
  EXPECT_EQ(m.vertices[n / 4], Vec3(0, 20, 0));
  EXPECT_EQ(m.vertices.back().z(), 50.0);
  expectOutwardFromAxis(m);
  const MeshReport r = validateMesh(m);
  expectClean(r);
  EXPECT_EQ(r.partClass, PartClass::Open);
  EXPECT_EQ(r.edgeCount, static_cast<size_t>(n * (3 * rings + 1)));
}

TEST(Primitives, ConeRadiusFollowsHeightAndApexBecomesPole)
{
  const TriangleMesh m = makeOpenCone(30.0, 10.0, 40.0, 36, 5);
  for (const Vec3& p : m.vertices) EXPECT_NEAR(radiusOf(p), 30.0 - 20.0 * p.z() / 40.0, 1e-12);
  expectOutwardFromAxis(m);
  const MeshReport open = validateMesh(m);
  expectClean(open);
  EXPECT_EQ(open.partClass, PartClass::Open);

  const TriangleMesh pointed = makeOpenCone(30.0, 0.0, 40.0, 36, 5);
  EXPECT_EQ(pointed.vertexCount(), 36u * 5u + 1u);
  EXPECT_EQ(pointed.vertices.back(), Vec3(0, 0, 40));
  expectOutwardFromAxis(pointed);
  const MeshReport closed = validateMesh(pointed);
  expectClean(closed);
  EXPECT_EQ(closed.partClass, PartClass::Closed);
}

TEST(Primitives, HemisphereHasPoleAndBaseRingOnTheSphere)
{
  const int n = 48, rings = 12;
  const double R = 35.0;
  const TriangleMesh m = makeHemisphere(R, n, rings);
  EXPECT_EQ(m.vertexCount(), static_cast<size_t>(n * rings + 1));
  EXPECT_EQ(m.faceCount(), static_cast<size_t>(2 * n * (rings - 1) + n));
  EXPECT_EQ(m.vertices.back(), Vec3(0, 0, R));
  for (int j = 0; j < n; ++j) EXPECT_EQ(m.vertices[j].z(), 0.0);
  for (const Vec3& p : m.vertices) EXPECT_NEAR(p.norm(), R, 1e-13 * R);
  for (size_t f = 0; f < m.faceCount(); ++f)  // outward = away from the centre
    EXPECT_GT(m.faceNormal(f).dot(test::centroidOf(m, static_cast<int>(f))), 0.0);
  const MeshReport r = validateMesh(m);
  expectClean(r);
  EXPECT_EQ(r.partClass, PartClass::Closed);
  ASSERT_EQ(r.boundaryLoops.size(), 1u);
  EXPECT_NEAR(r.boundaryLoops[0].length, n * 2.0 * R * std::sin(kPi / n), 1e-10);
}

TEST(Primitives, FineHemisphereAreaApproachesAnalytic)
{
  const double R = 10.0;
  const TriangleMesh m = makeHemisphere(R, 256, 64);
  EXPECT_NEAR(m.area(), 2.0 * kPi * R * R, 1e-3 * 2.0 * kPi * R * R);
}

TEST(Primitives, RevolvedSphereIsWatertightWithOutwardVolume)
{
  const double R = 5.0;
  std::vector<Eigen::Vector2d> profile;
  const int k = 40;
  profile.emplace_back(0.0, -R);
  for (int i = 1; i < k; ++i) {
    const double phi = -0.5 * kPi + kPi * i / k;
    profile.emplace_back(R * std::cos(phi), R * std::sin(phi));
  }
  profile.emplace_back(0.0, R);
  const TriangleMesh m = makeRevolved(profile, 80);
  const double exact = 4.0 / 3.0 * kPi * R * R * R;
  EXPECT_NEAR(test::signedVolume(m), exact, 0.01 * exact);
  const MeshReport r = validateMesh(m);
  expectClean(r);
  EXPECT_TRUE(r.boundaryLoops.empty());
  EXPECT_EQ(r.partClass, PartClass::Unsupported);
  EXPECT_NE(r.classReason.find("watertight"), std::string::npos);
}

// A bent tube: every vertex on the torus, faces looking away from the guide, open at both ends, and
// (Pappus) the area of the profile's circumference swept along the bend.
TEST(Primitives, BentTubeLiesOnItsTorusAndFacesOutwards)
{
  const double R = 50.0, r = 15.0, angle = 0.5 * kPi;
  const TriangleMesh m = makeBentTube(R, r, angle, 120, 80);
  EXPECT_EQ(m.faceCount(), 2u * 120 * 80);
  const auto guideAt = [&](const Vec3& p) {  // the nearest guide point: the torus's centre circle
    const Vec3 fromAxis = Vec3(p.x() + R, 0.0, p.z());
    return Vec3(Vec3(-R, 0.0, 0.0) + R * fromAxis.normalized());
  };
  for (const Vec3& p : m.vertices) EXPECT_NEAR((p - guideAt(p)).norm(), r, 1e-9);
  for (size_t f = 0; f < m.faceCount(); f += 37) {
    const Vec3 c = test::centroidOf(m, static_cast<int>(f));
    EXPECT_GT(m.faceNormal(f).dot(c - guideAt(c)), 0.0) << "face " << f;
  }
  EXPECT_EQ(m.vertices[0], Vec3(r, 0.0, 0.0));
  const MeshReport rep = validateMesh(m);
  expectClean(rep);
  EXPECT_EQ(rep.partClass, PartClass::Open);
  EXPECT_EQ(rep.boundaryLoops.size(), 2u);
  EXPECT_NEAR(m.area(), 2.0 * kPi * r * R * angle, 1e-3 * 2.0 * kPi * r * R * angle);
  EXPECT_THROW(makeBentTube(10.0, 15.0, angle, 12, 4), InputError);
  EXPECT_THROW(makeBentTube(50.0, 15.0, 7.0, 12, 4), InputError);
}

// The torus feature on a pipe: every vertex on the torus, the base edge on the cylinder x^2 + z^2 = 32^2,
// the top ring where the bend ends (004_bd0df31205c0c3c0.txt Eq. 2.17-2.19).
TEST(Primitives, TorusOnACylinderStartsOnThePipe)
{
  const double R = 50.0, r = 15.0, Rc = 32.0, angle = 0.5 * kPi;
  const TriangleMesh m = makeTorusOnCylinder(R, r, Rc, angle, 60, 40);
  const MeshReport rep = validateMesh(m);
  expectClean(rep);
  ASSERT_EQ(rep.boundaryLoops.size(), 2u);
  for (int v : rep.boundaryLoops.front().vertices)
    EXPECT_NEAR(std::hypot(m.vertices[size_t(v)].x(), m.vertices[size_t(v)].z()), Rc, 1e-9);
  for (int v : rep.boundaryLoops.back().vertices) EXPECT_NEAR(m.vertices[size_t(v)].x(), -R, 1e-9);
  for (const Vec3& p : m.vertices) EXPECT_NEAR(std::hypot(std::hypot(p.x() + R, p.z()) - R, p.y()), r, 1e-9);
  EXPECT_THROW(makeTorusOnCylinder(R, r, 10.0, angle, 12, 4), InputError);  // inside the tube: no cut
}

// A pipe to build on: on its radius about the asked axis, centred; a huge one coarsened to about 200,000
// triangles.
TEST(Primitives, PipeAboutAnAxisIsCentredAndBounded)
{
  const TriangleMesh y = makePipeAbout(32.0, 'y', 100.0);
  for (const Vec3& p : y.vertices) {
    EXPECT_NEAR(std::hypot(p.x(), p.z()), 32.0, 1e-9);
    EXPECT_LE(std::abs(p.y()), 50.0 + 1e-9);
  }
  const TriangleMesh huge = makePipeAbout(1e5, 'x', 1e5);
  EXPECT_LE(huge.faceCount(), 210000u);
  EXPECT_NEAR(std::hypot(huge.vertices[7].y(), huge.vertices[7].z()), 1e5, 1e-6);
  EXPECT_THROW(makePipeAbout(32.0, 'w', 100.0), InputError);
}

TEST(Primitives, TetrahedronIsRegularAndClosed)
{
  const double a = 6.0;
  const TriangleMesh m = makeTetrahedron(a);
  ASSERT_EQ(m.faceCount(), 4u);
  for (const Face& f : m.faces)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR((m.vertices[f[k]] - m.vertices[f[(k + 1) % 3]]).norm(), a, 1e-12);
  EXPECT_NEAR(test::signedVolume(m), a * a * a / (6.0 * std::sqrt(2.0)), 1e-12);
  EXPECT_NEAR(m.area(), std::sqrt(3.0) * a * a, 1e-12);
  EXPECT_TRUE(m.bounds().center().isZero(1e-15));
}

TEST(Primitives, SegmentsAndRingsForEdge)
{
  EXPECT_EQ(segmentsForEdge(10.0, 1.0), 63);  // 2*pi*10 = 62.8
  EXPECT_EQ(segmentsForEdge(1.0, 100.0), 3);
  EXPECT_EQ(ringsForEdge(50.0, 2.0), 25);
  EXPECT_EQ(ringsForEdge(1.0, 5.0), 1);
  const int n = segmentsForEdge(20.0, 2.0);
  const TriangleMesh m = makeOpenCylinder(20.0, 40.0, n, ringsForEdge(40.0, 2.0));
  // Ring edges are 2 mm to within rounding of the count; with the diagonals the mean is about 14 % longer.
  EXPECT_NEAR(2.0 * 20.0 * std::sin(kPi / n), 2.0, 0.02);
  EXPECT_NEAR(m.meanEdgeLength(), 2.0 * (2.0 + std::sqrt(2.0)) / 3.0, 0.05);
  EXPECT_THROW(segmentsForEdge(10.0, 0.0), InputError);
}

TEST(Primitives, InvalidInputsThrowInputError)
{
  EXPECT_THROW(makeOpenCylinder(10.0, 10.0, 2, 1), InputError);
  EXPECT_THROW(makeOpenCylinder(-1.0, 10.0, 8, 1), InputError);
  EXPECT_THROW(makeOpenCylinder(1.0, 10.0, 8, 0), InputError);
  EXPECT_THROW(makeOpenCone(0.0, 0.0, 10.0, 8, 1), InputError);
  EXPECT_THROW(makeHemisphere(std::nan(""), 8, 2), InputError);
  EXPECT_THROW(makeTetrahedron(0.0), InputError);
  EXPECT_THROW(makeRevolved({{1.0, 0.0}}, 8), InputError);
  EXPECT_THROW(makeRevolved({{1.0, 0.0}, {0.0, 1.0}, {1.0, 2.0}}, 8), InputError);  // pinched in the middle
  EXPECT_THROW(makeRevolved({{1.0, 0.0}, {1.0, 0.0}, {1.0, 2.0}}, 8), InputError);  // repeated point
  EXPECT_THROW(makeRevolved({{0.0, 0.0}, {0.0, 1.0}}, 8), InputError);              // on the axis
}
