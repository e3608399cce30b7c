#include "spira/planning/field_smoothing.h"

#include "spira/field/cotan_laplacian.h"
#include "spira/field/fill_ordering.h"
#include "spira/field/mesh_adjacency.h"
#include "spira/field/sparse_cholesky.h"

namespace spira {

std::vector<double> smoothField(const TriangleMesh& mesh, const std::vector<double>& field, double timeScale)
{
  const MeshAdjacency adjacency = buildMeshAdjacency(mesh);
  const CotanLaplacian op = buildCotanLaplacian(mesh, adjacency);
  const double t = timeScale * op.meanEdgeLength * op.meanEdgeLength;
  SymmetricSparseMatrix system = op.stiffness;
  for (double& v : system.values) v *= t;
  std::vector<double> rhs(field.size());
  for (int j = 0; j < system.size; ++j) {
    const double a = op.vertexArea[static_cast<size_t>(j)];
    // A vertex without area has no equation of its own: pin it to its value.
    system.values[static_cast<size_t>(system.columnStart[static_cast<size_t>(j)])] += a > 0 ? a : 1.0;
    rhs[static_cast<size_t>(j)] = (a > 0 ? a : 1.0) * field[static_cast<size_t>(j)];
  }
  const CholeskyAnalysis analysis(system, geometricNestedDissection(mesh.vertices, adjacency));
  const CholeskyFactor factor(analysis, system);
  return factor.solve(rhs);
}

}  // namespace spira
