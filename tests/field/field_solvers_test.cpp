// The building blocks under the field solvers: adjacency, cotan operators, ordering, Cholesky.
#include <algorithm>
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "field/field_test_meshes.h"
#include "spira/base/error.h"
#include "spira/field/cotan_laplacian.h"
#include "spira/field/fill_ordering.h"
#include "spira/field/mesh_adjacency.h"
#include "spira/field/sparse_cholesky.h"

namespace spira {
namespace {

TEST(MeshAdjacency, TubeHasTwoFreeRingsAndOneComponent)
{
  const test::RingMesh tube = test::tubeMesh(5.0, 5.0, 0.7);
  const MeshAdjacency a = buildMeshAdjacency(tube.mesh);
  EXPECT_EQ(a.componentCount, 1);
  std::vector<char> expected(tube.mesh.vertices.size(), 0);
  for (int v : tube.lower) expected[v] = 1;
  for (int v : tube.upper) expected[v] = 1;
  EXPECT_EQ(a.onBoundary, expected);
  EXPECT_EQ(int(a.corners.size()), 3 * int(tube.mesh.faces.size()));
  // Symmetric neighbour lists; every face edge present.
  for (const Face& f : tube.mesh.faces)
    for (int k = 0; k < 3; ++k) {
      const int u = f[k], w = f[(k + 1) % 3];
      EXPECT_TRUE(std::binary_search(a.neighbors.begin() + a.neighborStart[u],
                                     a.neighbors.begin() + a.neighborStart[u + 1], w));
      EXPECT_TRUE(std::binary_search(a.neighbors.begin() + a.neighborStart[w],
                                     a.neighbors.begin() + a.neighborStart[w + 1], u));
    }
}

TEST(MeshAdjacency, RejectsOutOfRangeFaces)
{
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  m.faces = {{0, 1, 3}};
  EXPECT_THROW(buildMeshAdjacency(m), InputError);
}

TEST(CotanLaplacian, AnnihilatesConstantsAndIntegratesArea)
{
  const test::RingMesh dome = test::domeMesh(10.0, 0.8);
  const MeshAdjacency a = buildMeshAdjacency(dome.mesh);
  const CotanLaplacian op = buildCotanLaplacian(dome.mesh, a);
  const std::vector<double> ones(dome.mesh.vertices.size(), 1.0);
  for (double x : op.stiffness.multiply(ones)) EXPECT_NEAR(x, 0.0, 1e-10);
  double area = 0.0;
  for (double x : op.vertexArea) area += x;
  EXPECT_NEAR(area, 2.0 * M_PI * 100.0, 0.01 * 2.0 * M_PI * 100.0);  // inscribed polyhedron
  EXPECT_NEAR(op.meanEdgeLength, 0.8, 0.1);
}

TEST(CotanLaplacian, EquilateralWeightsAreHalfCotSixty)
{
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, std::sqrt(3.0) / 2, 0)};
  m.faces = {{0, 1, 2}};
  const CotanLaplacian op = buildCotanLaplacian(m, buildMeshAdjacency(m));
  const double w = 0.5 / std::tan(M_PI / 3);
  EXPECT_NEAR(op.stiffness.values[op.stiffness.find(1, 0)], -w, 1e-14);
  EXPECT_NEAR(op.stiffness.diagonal(0), 2 * w, 1e-14);
  EXPECT_NEAR(op.vertexArea[2], std::sqrt(3.0) / 12, 1e-14);
}

TEST(FillOrdering, IsAPermutationThatReducesFill)
{
  const test::RingMesh dome = test::domeMesh(20.0, 0.5);
  const MeshAdjacency a = buildMeshAdjacency(dome.mesh);
  const std::vector<int> order = geometricNestedDissection(dome.mesh.vertices, a);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(order.size());
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(sorted, identity);
  const SymmetricSparseMatrix pattern = a.lowerPattern();
  const CholeskyAnalysis nd(pattern, order);
  const CholeskyAnalysis natural(pattern, identity);  // rings in order: a wide band
  EXPECT_LT(nd.factorNonZeros(), 0.5 * natural.factorNonZeros());
  const CholeskyAnalysis metis(pattern, CholmodOrdering::Metis);
  EXPECT_LT(nd.factorNonZeros(), 1.6 * metis.factorNonZeros());
}

TEST(SparseCholesky, SolvesASymmetricPositiveDefiniteSystem)
{
  const test::RingMesh tube = test::tubeMesh(4.0, 4.0, 0.5);
  const MeshAdjacency a = buildMeshAdjacency(tube.mesh);
  CotanLaplacian op = buildCotanLaplacian(tube.mesh, a);
  SymmetricSparseMatrix k = op.stiffness;
  for (int v = 0; v < k.size; ++v) k.values[k.columnStart[v]] += op.vertexArea[v];
  std::vector<double> x(k.size);
  for (int v = 0; v < k.size; ++v) x[v] = std::sin(0.37 * v) + tube.mesh.vertices[v].z();
  const std::vector<double> b = k.multiply(x);
  const CholeskyAnalysis analysis(k, geometricNestedDissection(tube.mesh.vertices, a));
  const CholeskyFactor factor(analysis, k);
  const std::vector<double> y = factor.solve(b);
  for (int v = 0; v < k.size; ++v) EXPECT_NEAR(y[v], x[v], 1e-10);
  EXPECT_THROW(factor.solve({1.0}), InternalError);
}

TEST(SparseCholesky, RefusesAnIndefiniteMatrix)
{
  const test::RingMesh tube = test::tubeMesh(4.0, 4.0, 1.0);
  const MeshAdjacency a = buildMeshAdjacency(tube.mesh);
  SymmetricSparseMatrix k = buildCotanLaplacian(tube.mesh, a).stiffness;
  for (double& x : k.values) x = -x;  // negative semi-definite
  const CholeskyAnalysis analysis(k, CholmodOrdering::Amd);
  EXPECT_THROW(CholeskyFactor(analysis, k), AlgorithmError);
}

TEST(SymmetricSparseMatrix, FixedRowsReproduceBoundaryValues)
{
  const test::RingMesh tube = test::tubeMesh(4.0, 6.0, 0.5);
  const MeshAdjacency a = buildMeshAdjacency(tube.mesh);
  const SymmetricSparseMatrix k = buildCotanLaplacian(tube.mesh, a).stiffness;
  std::vector<char> fixed(k.size, 0);
  std::vector<double> values(k.size, 0.0);
  for (int v : tube.lower) fixed[v] = 1;
  for (int v : tube.upper) fixed[v] = 1, values[v] = 3.0;
  const SymmetricSparseMatrix system = withFixedRows(k, fixed, 2.0);
  const CholeskyFactor factor(CholeskyAnalysis(system, CholmodOrdering::Amd), system);
  const std::vector<double> u = factor.solve(fixedRowsLift(k, fixed, values, 2.0));
  for (int v = 0; v < k.size; ++v) EXPECT_NEAR(u[v], 3.0 * tube.mesh.vertices[v].z() / 6.0, 1e-9);
}

}  // namespace
}  // namespace spira
