#include "spira/field/harmonic_field.h"

#include <limits>
#include <string>

#include "spira/base/error.h"
#include "spira/field/cotan_laplacian.h"
#include "spira/field/fill_ordering.h"
#include "spira/field/mesh_adjacency.h"
#include "spira/field/sparse_cholesky.h"

namespace spira {
namespace {

void checkSet(const std::vector<int>& set, const char* name, int n)
{
  if (set.empty())
    throw InputError(std::string("the ") + name + " boundary has no vertices",
                     "an open part needs both a lower and an upper free edge");
  for (int v : set)
    if (v < 0 || v >= n)
      throw InputError(std::string("the ") + name + " boundary names vertex " + std::to_string(v) +
                           ", which does not exist (the mesh has " + std::to_string(n) + " vertices)",
                       "pass vertex ids of this mesh");
}

}  // namespace

std::vector<double> harmonicField(const TriangleMesh& mesh, const std::vector<int>& lower,
                                  const std::vector<int>& upper, Progress& progress)
{
  const int n = int(mesh.vertices.size());
  checkSet(lower, "lower", n);
  checkSet(upper, "upper", n);
  progress.report(0.0, "field: mesh operators");
  const MeshAdjacency adjacency = buildMeshAdjacency(mesh);
  const CotanLaplacian op = buildCotanLaplacian(mesh, adjacency);
  progress.checkCancel();

  std::vector<char> fixed(n, 0);
  std::vector<double> value(n, 0.0);
  for (int v : lower) fixed[v] = 1;
  for (int v : upper) {
    if (fixed[v])
      throw InputError("vertex " + std::to_string(v) + " is on both the lower and the upper boundary",
                       "the two free edges of an open part must be separate loops");
    fixed[v] = 1;
    value[v] = 1.0;
  }
  // Parts with no boundary value (and vertices without faces) have no solution: fix them to NaN.
  std::vector<char> componentHasValue(adjacency.componentCount, 0);
  for (int v = 0; v < n; ++v)
    if (fixed[v]) componentHasValue[adjacency.component[v]] = 1;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<char> undetermined(n, 0);
  for (int v = 0; v < n; ++v) {
    if (!componentHasValue[adjacency.component[v]] || !(op.stiffness.diagonal(v) > 0.0)) {
      undetermined[v] = !fixed[v];
      fixed[v] = 1;
    }
  }

  double scale = 0.0;
  for (int v = 0; v < n; ++v) scale += op.stiffness.diagonal(v);
  scale = scale > 0.0 ? scale / n : 1.0;
  const SymmetricSparseMatrix system = withFixedRows(op.stiffness, fixed, scale);
  const std::vector<double> rhs = fixedRowsLift(op.stiffness, fixed, value, scale);
  progress.report(0.2, "field: ordering");
  progress.checkCancel();
  const CholeskyAnalysis analysis(system, geometricNestedDissection(mesh.vertices, adjacency));
  progress.report(0.35, "field: factorising");
  progress.checkCancel();
  const CholeskyFactor factor(analysis, system);
  progress.report(0.9, "field: solving");
  progress.checkCancel();
  std::vector<double> u = factor.solve(rhs);
  for (int v = 0; v < n; ++v)
    if (undetermined[v]) u[v] = nan;
  progress.report(1.0, "field: harmonic");
  return u;
}

std::vector<double> harmonicField(const TriangleMesh& mesh, const std::vector<int>& lower,
                                  const std::vector<int>& upper)
{
  NullProgress none;
  return harmonicField(mesh, lower, upper, none);
}

}  // namespace spira
