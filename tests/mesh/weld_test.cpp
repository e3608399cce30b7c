#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "mesh/mesh_test_shapes.h"
#include "spira/base/error.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/mesh/mesh_weld.h"
#include "spira/mesh/union_find.h"

using namespace spira;

namespace {

// Welded faces must describe the same triangles, corner by corner, as the soup they came from.
void expectSameTriangles(const TriangleMesh& welded, const std::vector<Vec3>& soup)
{
  ASSERT_EQ(welded.faceCount() * 3, soup.size());
  for (size_t f = 0; f < welded.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(welded.vertices[welded.faces[f][k]], soup[3 * f + k]) << f;
}

// Clusters by brute force: every pair closer than tol, transitively. Independent of the grid.
size_t bruteForceClusterCount(const std::vector<Vec3>& p, double tol)
{
  UnionFind uf(p.size());
  size_t clusters = p.size();
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j)
      if ((p[i] - p[j]).norm() < tol && uf.unite(static_cast<int>(i), static_cast<int>(j))) --clusters;
  return clusters;
}

// The same, for many points: a sweep along x instead of all pairs.
size_t sweepClusterCount(const std::vector<Vec3>& p, double tol)
{
  std::vector<int> order(p.size());
  for (size_t i = 0; i < p.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return p[a].x() < p[b].x(); });
  UnionFind uf(p.size());
  size_t clusters = p.size();
  for (size_t i = 0; i < order.size(); ++i)
    for (size_t j = i + 1; j < order.size() && p[order[j]].x() - p[order[i]].x() < tol; ++j)
      if ((p[order[i]] - p[order[j]]).norm() < tol && uf.unite(order[i], order[j])) --clusters;
  return clusters;
}

std::vector<Vec3> randomPoints(size_t n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> p(n);
  for (Vec3& q : p) q = Vec3(u(rng), u(rng), u(rng));
  return p;
}

Vec3 randomDirection(std::mt19937& rng)
{
  std::normal_distribution<double> g;
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

}  // namespace

TEST(Weld, CylinderSoupWeldsBackToTheIndexedMesh)
{
  const TriangleMesh cyl = makeOpenCylinder(20.0, 35.0, 40, 9);
  const std::vector<Vec3> soup = test::soupOf(cyl);
  WeldStats stats;
  const TriangleMesh welded = weldTriangleSoup(soup, kDefaultWeldTolerance, &stats);
  EXPECT_EQ(welded.vertexCount(), cyl.vertexCount());
  expectSameTriangles(welded, soup);
  EXPECT_EQ(stats.inputVertices, soup.size());
  EXPECT_EQ(stats.outputVertices, cyl.vertexCount());
  EXPECT_NEAR(stats.tolerance, kDefaultWeldTolerance * cyl.bounds().diagonal(), 1e-18);
  const MeshReport r = validateMesh(welded);
  EXPECT_TRUE(r.issues.empty());
  EXPECT_EQ(r.partClass, PartClass::Open);
}

TEST(Weld, VerticesAreNumberedByFirstUse)
{
  const TriangleMesh cyl = makeOpenCylinder(5.0, 5.0, 8, 2);
  const TriangleMesh welded = weldTriangleSoup(test::soupOf(cyl));
  EXPECT_EQ(welded.faces[0], (Face{0, 1, 2}));
  int next = 0;
  for (const Face& f : welded.faces)
    for (int v : f) {
      ASSERT_LE(v, next);
      if (v == next) ++next;
    }
  // An already welded mesh comes back unchanged.
  EXPECT_EQ(weldVertices(cyl), cyl);
}

TEST(Weld, ToleranceIsRelativeToTheBoundingBox)
{
  const TriangleMesh hemi = makeHemisphere(10.0, 32, 8);
  for (double scale : {1e-3, 1.0, 1e4}) {
    TriangleMesh scaled = hemi;
    for (Vec3& v : scaled.vertices) v *= scale;
    const std::vector<Vec3> soup = test::soupOf(scaled);
    const TriangleMesh welded = weldTriangleSoup(soup, 1e-3);
    EXPECT_EQ(welded.vertexCount(), hemi.vertexCount()) << scale;
    EXPECT_EQ(welded.faces, weldTriangleSoup(test::soupOf(hemi), 1e-3).faces) << scale;
    expectSameTriangles(welded, soup);
  }
}

TEST(Weld, NearDuplicatesMergeWithinToleranceOnly)
{
  // Two triangles sharing edge p0-p1; the second triangle's copy of p1 is moved by `offset`.
  const auto twoTriangles = [](double offset) {
    const Vec3 p0(0, 0, 0), p1(10, 0, 0), p2(5, 8, 0), p3(5, -8, 0);
    return std::vector<Vec3>{p0, p1, p2, p1 + Vec3(0, 0, offset), p0, p3};
  };
  const double diag = std::sqrt(10.0 * 10.0 + 16.0 * 16.0);
  const double tol = 1e-6 * diag;
  EXPECT_EQ(weldTriangleSoup(twoTriangles(0.5 * tol), 1e-6).vertexCount(), 4u);
  EXPECT_EQ(weldTriangleSoup(twoTriangles(2.0 * tol), 1e-6).vertexCount(), 5u);
  // The merged vertex keeps the position of its first corner.
  EXPECT_EQ(weldTriangleSoup(twoTriangles(0.5 * tol), 1e-6).vertices[1], Vec3(10, 0, 0));
}

TEST(Weld, MergingIsTransitive)
{
  const double tol = 1e-4 * std::sqrt(3.0);  // diagonal of the unit cube spanned below
  const Vec3 a(0.3, 0.3, 0.3), step(0.7 * tol, 0, 0);
  // a, a+step, a+2*step: the ends are 1.4 tol apart but joined through the middle.
  std::vector<Vec3> soup = {Vec3(0, 0, 0), Vec3(1, 1, 1), a, a + 2.0 * step, Vec3(1, 0, 0), a + step};
  const TriangleMesh welded = weldTriangleSoup(soup, 1e-4);
  EXPECT_EQ(welded.vertexCount(), 4u);
  EXPECT_EQ(welded.faces[1], (Face{2, 3, 2}));  // kept although it collapsed: validation reports it
  EXPECT_TRUE(validateMesh(welded).hasIssue(MeshIssueKind::DegenerateFace));
}

TEST(Weld, RandomClustersMatchBruteForce)
{
  std::mt19937 rng(7);
  const std::vector<Vec3> seeds = randomPoints(600, 11);
  const double relTol = 2e-3;
  for (double spread : {0.3, 0.9, 3.0}) {
    std::vector<Vec3> points = seeds;
    points.push_back(Vec3(0, 0, 0));
    points.push_back(Vec3(1, 1, 1));
    const double tol = relTol * std::sqrt(3.0);
    for (size_t i = 0; i < seeds.size(); ++i)
      for (int copies = 0; copies < 2; ++copies)
        points.push_back(seeds[i] + spread * tol * randomDirection(rng));
    while (points.size() % 3 != 0) points.push_back(points.back());
    BoundingBox box;
    for (const Vec3& q : points) box.extend(q);  // copies may stick out of the unit cube
    WeldStats stats;
    const TriangleMesh welded = weldTriangleSoup(points, relTol, &stats);
    EXPECT_DOUBLE_EQ(stats.tolerance, relTol * box.diagonal());
    EXPECT_EQ(welded.vertexCount(), bruteForceClusterCount(points, stats.tolerance)) << spread;
  }
}

TEST(Weld, ManyNearPairsInEveryDirectionMatchSweep)
{
  // 100k points, each with a copy just inside or just outside the tolerance in a random
  // direction: pairs straddle grid cells along every axis and diagonal.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.5, 1.5);
  std::vector<Vec3> points = randomPoints(100000, 5);
  points.push_back(Vec3(0, 0, 0));
  points.push_back(Vec3(1, 1, 1));
  const double relTol = 1e-6;
  const double tol = relTol * std::sqrt(3.0);
  for (size_t i = 0; i < 100000; ++i) points.push_back(points[i] + u(rng) * tol * randomDirection(rng));
  while (points.size() % 3 != 0) points.push_back(points.back());
  WeldStats stats;
  const TriangleMesh welded = weldTriangleSoup(points, relTol, &stats);
  const size_t expected = sweepClusterCount(points, stats.tolerance);
  EXPECT_LT(expected, 190000u);  // about half the copies merge
  EXPECT_GT(expected, 110000u);
  EXPECT_EQ(welded.vertexCount(), expected);
}

TEST(Weld, ZeroToleranceMergesOnlyExactCopiesAndSignedZeros)
{
  std::vector<Vec3> soup = {Vec3(0, 0, 0),       Vec3(1, 0, 0),      Vec3(0, 1, 0),
                            Vec3(-0.0, 0, -0.0), Vec3(1, 0, 1e-300), Vec3(0, 1, 0)};
  const TriangleMesh welded = weldTriangleSoup(soup, 0.0);
  EXPECT_EQ(welded.vertexCount(), 4u);
  EXPECT_EQ(welded.faces[1], (Face{0, 3, 2}));
}

TEST(Weld, WeldVerticesDropsUnreferencedAndKeepsFaceOrder)
{
  TriangleMesh m = makeTetrahedron(2.0);
  m.vertices.insert(m.vertices.begin(), Vec3(50, 50, 50));  // unreferenced, first
  for (Face& f : m.faces)
    for (int& v : f) ++v;
  m.vertices.push_back(m.vertices[1]);  // exact copy of vertex 1, used by the last face
  std::replace(m.faces[3].begin(), m.faces[3].end(), 1, 5);
  WeldStats stats;
  const TriangleMesh w = weldVertices(m, kDefaultWeldTolerance, &stats);
  EXPECT_EQ(w, makeTetrahedron(2.0));
  EXPECT_EQ(stats.inputVertices, 6u);
  EXPECT_EQ(stats.outputVertices, 4u);
  EXPECT_EQ(stats.removedUnreferenced, 1u);
}

TEST(Weld, NonFiniteCornersStayTheirOwnVertices)
{
  const TriangleMesh cyl = makeOpenCylinder(10.0, 10.0, 16, 3);
  std::vector<Vec3> soup = test::soupOf(cyl);
  soup[40] = Vec3(std::nan(""), 0, 0);
  soup[41] = Vec3(std::nan(""), 0, 0);  // same bits as soup[40], still not merged
  soup[77].z() = -INFINITY;
  const TriangleMesh welded = weldTriangleSoup(soup);
  EXPECT_EQ(welded.vertexCount(), cyl.vertexCount() + 3);
  const MeshReport r = validateMesh(welded);
  EXPECT_EQ(r.issueCount(MeshIssueKind::NonFiniteCoordinate), 3u);

  std::vector<Vec3> allNan(9, Vec3(std::nan(""), std::nan(""), std::nan("")));
  EXPECT_EQ(weldTriangleSoup(allNan).vertexCount(), 9u);
  EXPECT_EQ(weldTriangleSoup({}).vertexCount(), 0u);
}

TEST(Weld, BadInputThrows)
{
  EXPECT_THROW(weldTriangleSoup(std::vector<Vec3>(4, Vec3::Zero())), InputError);
  EXPECT_THROW(weldTriangleSoup(std::vector<Vec3>(3, Vec3::Zero()), -1.0), InputError);
  TriangleMesh bad = makeTetrahedron(1.0);
  bad.faces[0][0] = 9;
  EXPECT_THROW(weldVertices(bad), InputError);
}

TEST(Weld, LargeSoupFromManyPartitionsWeldsExactly)
{
  // Enough corners for the parallel, partitioned duplicate pass to use thousands of partitions.
  const TriangleMesh cyl = makeOpenCylinder(30.0, 60.0, 400, 120);
  const std::vector<Vec3> soup = test::soupOf(cyl);
  const TriangleMesh welded = weldTriangleSoup(soup);
  EXPECT_EQ(welded.vertexCount(), cyl.vertexCount());
  expectSameTriangles(welded, soup);
  EXPECT_EQ(validateMesh(welded).partClass, PartClass::Open);
}

TEST(Weld, OneStrayFarVertexDoesNotCollapseThePart)
{
  // A hemisphere (edges about 2 mm) plus one sliver triangle reaching out to x = 1e9: the bounding
  // box alone would make the tolerance 1e-7 * 1e9 = 100 mm and weld the hemisphere to a point.
  const TriangleMesh hemi = makeHemisphere(10.0, 32, 8);
  std::vector<Vec3> soup = test::soupOf(hemi);
  soup.insert(soup.end(), {hemi.vertices[0], hemi.vertices[1], Vec3(1e9, 0, 0)});
  WeldStats stats;
  const TriangleMesh welded = weldTriangleSoup(soup, kDefaultWeldTolerance, &stats);
  EXPECT_EQ(welded.vertexCount(), hemi.vertexCount() + 1);
  EXPECT_LT(stats.tolerance, 0.01);
  expectSameTriangles(welded, soup);
  // The same through weldVertices.
  TriangleMesh indexed = hemi;
  indexed.vertices.push_back(Vec3(1e9, 0, 0));
  indexed.faces.push_back(Face{0, 1, static_cast<int>(hemi.vertexCount())});
  EXPECT_EQ(weldVertices(indexed).vertexCount(), hemi.vertexCount() + 1);
}
