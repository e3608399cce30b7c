#include "spira/field/heat_distance.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "spira/base/error.h"
#include "spira/field/cotan_laplacian.h"
#include "spira/field/fill_ordering.h"
#include "spira/field/mesh_adjacency.h"
#include "spira/field/sparse_cholesky.h"

namespace spira {
namespace {

double meanDiagonal(const SymmetricSparseMatrix& m)
{
  double sum = 0.0;
  for (int j = 0; j < m.size; ++j) sum += m.diagonal(j);
  return m.size > 0 && sum > 0.0 ? sum / m.size : 1.0;
}

NullProgress& silentProgress()
{
  static NullProgress none;
  return none;
}

}  // namespace

struct HeatDistanceSolver::Impl {
  HeatDistanceOptions options;
  std::vector<Vec3> points;
  std::vector<Face> faces;
  MeshAdjacency adjacency;
  double h = 0.0, time = 0.0;
  // Vertices with no usable face (isolated, or only degenerate faces): decoupled identity rows.
  std::vector<char> isolated;
  std::vector<char> pinned;  // one vertex per component fixes the Poisson constant
  SymmetricSparseMatrix heat;
  double heatScale = 1.0, poissonScale = 1.0;
  // Heat put on each source. u decays like exp(-d / h) away from the sources, so with a unit
  // source it would underflow about 700 edges away; starting near the top of the double range
  // instead (u <= sourceHeat / A_min by the maximum principle) doubles the reach.
  double sourceHeat = 1.0;
  std::unique_ptr<CholeskyAnalysis> analysis;
  std::unique_ptr<CholeskyFactor> heatFactor, poissonFactor, dirichletFactor;
  std::vector<char> dirichletSet;  // the fixed vertices dirichletFactor was built for
  HeatDistanceStats stats;
  HeatDistanceSetupStats setup;

  void build(const TriangleMesh& mesh, Progress& progress);
  std::vector<double> heatSolve(const std::vector<int>& sources);
  std::vector<Vec3> unitDescent(const std::vector<double>& u, int& flatFaces) const;
  std::vector<double> divergence(const std::vector<Vec3>& x) const;
};

void HeatDistanceSolver::Impl::build(const TriangleMesh& mesh, Progress& progress)
{
  if (!(options.timeScale > 0.0) || !std::isfinite(options.timeScale))
    throw InputError("heat method time scale must be a positive number", "use 1 (t = h^2)");
  if (options.refinementSteps < 0)
    throw InputError("heat method refinement steps must not be negative",
                     "use 1 (0 is the plain heat method)");
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point a) {
    return std::chrono::duration<double>(Clock::now() - a).count();
  };
  auto start = Clock::now();
  points = mesh.vertices;
  faces = mesh.faces;
  progress.report(0.0, "field: mesh operators");
  adjacency = buildMeshAdjacency(mesh);
  const int n = adjacency.vertexCount();
  CotanLaplacian op = buildCotanLaplacian(mesh, adjacency);
  h = op.meanEdgeLength;
  time = options.timeScale * h * h;
  progress.checkCancel();

  isolated.assign(n, 0);
  pinned.assign(n, 0);
  std::vector<char> componentPinned(adjacency.componentCount, 0);
  for (int v = 0; v < n; ++v) {
    isolated[v] = !(op.stiffness.diagonal(v) > 0.0 && op.vertexArea[v] > 0.0);
    const int c = adjacency.component[v];
    if (!isolated[v] && !componentPinned[c]) pinned[v] = componentPinned[c] = 1;
  }

  double minArea = std::numeric_limits<double>::infinity();
  for (int v = 0; v < n; ++v)
    if (!isolated[v]) minArea = std::min(minArea, op.vertexArea[v]);
  sourceHeat = std::isfinite(minArea) ? 1e250 * minArea : 1.0;

  heat = op.stiffness;
  for (double& x : heat.values) x *= time;
  for (int v = 0; v < n; ++v) heat.values[heat.columnStart[v]] += op.vertexArea[v];
  heatScale = meanDiagonal(heat);
  heat = withFixedRows(heat, isolated, heatScale);
  poissonScale = meanDiagonal(op.stiffness);
  std::vector<char> poissonFixed(n);
  for (int v = 0; v < n; ++v) poissonFixed[v] = isolated[v] || pinned[v];
  const SymmetricSparseMatrix poisson = withFixedRows(op.stiffness, poissonFixed, poissonScale);
  op = CotanLaplacian();
  setup.operatorSeconds = seconds(start);
  progress.report(0.15, "field: ordering");
  progress.checkCancel();

  start = Clock::now();
  analysis = std::make_unique<CholeskyAnalysis>(heat, geometricNestedDissection(points, adjacency));
  adjacency.neighbors = std::vector<int>();  // only the ordering needed them
  adjacency.neighborStart = std::vector<int>();
  setup.analysisSeconds = seconds(start);
  setup.factorNonZeros = analysis->factorNonZeros();
  progress.report(0.25, "field: factorising");
  progress.checkCancel();
  start = Clock::now();
  // The two factorisations are independent: on two cores they cost the time of one.
  tbb::parallel_invoke([&] { heatFactor = std::make_unique<CholeskyFactor>(*analysis, heat); },
                       [&] { poissonFactor = std::make_unique<CholeskyFactor>(*analysis, poisson); });
  setup.factorSeconds = seconds(start);
  progress.report(1.0, "field: factorised");
  progress.checkCancel();
}

std::vector<double> HeatDistanceSolver::Impl::heatSolve(const std::vector<int>& sources)
{
  const int n = int(points.size());
  std::vector<double> delta(n, 0.0);
  for (int s : sources) delta[s] = isolated[s] ? 0.0 : sourceHeat;

  std::vector<char> fixed(n, 0);
  int fixedCount = 0;
  if (options.averageBoundaryConditions) {
    for (int v = 0; v < n; ++v) fixed[v] = adjacency.onBoundary[v] && !isolated[v];
    for (int s : sources) fixed[s] = 0;
    for (int v = 0; v < n; ++v) fixedCount += fixed[v];
  }
  stats.usedDirichlet = fixedCount > 0;
  stats.dirichletVertices = fixedCount;
  if (fixedCount == 0) return heatFactor->solve(delta);

  // Free vertices not heated: u = 0 there in the Dirichlet half. Only that half depends on the
  // source set, so its factor is kept while the set of fixed vertices stays the same.
  if (!dirichletFactor || dirichletSet != fixed) {
    dirichletFactor.reset();
    std::vector<char> all = fixed;
    for (int v = 0; v < n; ++v) all[v] = all[v] || isolated[v];
    dirichletFactor = std::make_unique<CholeskyFactor>(*analysis, withFixedRows(heat, all, heatScale));
    dirichletSet = fixed;
  }
  std::vector<double> uN, uD;
  std::vector<double> deltaD = delta;
  for (int v = 0; v < n; ++v)
    if (fixed[v]) deltaD[v] = 0.0;
  tbb::parallel_invoke([&] { uN = heatFactor->solve(delta); }, [&] { uD = dirichletFactor->solve(deltaD); });
  for (int v = 0; v < n; ++v) uN[v] = 0.5 * (uN[v] + uD[v]);
  return uN;
}

// X_f = -grad u / |grad u| per face; faces where grad u vanishes or is not finite get X = 0
// and are counted in `flatFaces`.
std::vector<Vec3> HeatDistanceSolver::Impl::unitDescent(const std::vector<double>& u, int& flatFaces) const
{
  const int faceCount = int(faces.size());
  std::vector<Vec3> x(faceCount, Vec3::Zero());
  std::vector<int> flat(faceCount, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, faceCount, 8192), [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f) {
      const Face& t = faces[f];
      const Vec3 &p0 = points[t[0]], &p1 = points[t[1]], &p2 = points[t[2]];
      const Vec3 normal = (p1 - p0).cross(p2 - p0);
      // A_f * grad u, up to the positive factor 1/(2|N|), which the normalisation removes.
      const Vec3 g = normal.cross(u[t[0]] * (p2 - p1) + u[t[1]] * (p0 - p2) + u[t[2]] * (p1 - p0));
      // Scaled before normalising: u spans hundreds of decades, and g.norm() would square it.
      const double scale = g.cwiseAbs().maxCoeff();
      if (scale > 0.0 && std::isfinite(scale))
        x[f] = -(g / scale).normalized();
      else
        flat[f] = 1;
    }
  });
  flatFaces = 0;
  for (int d : flat) flatFaces += d;
  return x;
}

// b_i = sum over the faces f around i of A_f grad(phi_i) . X_f, where A_f grad(phi_i) =
// (N_f x e_i) / 2 with e_i the edge opposite i, counter-clockwise. This is minus the integrated
// divergence of Appendix A.5, the right-hand side of (-L_C) phi = -div X.
std::vector<double> HeatDistanceSolver::Impl::divergence(const std::vector<Vec3>& x) const
{
  const int n = int(points.size());
  std::vector<double> b(n, 0.0);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v < r.end(); ++v) {
      if (pinned[v] || isolated[v]) continue;
      double sum = 0.0;
      for (int c = adjacency.cornerStart[v]; c < adjacency.cornerStart[v + 1]; ++c) {
        const int f = adjacency.corners[c] / 3, k = adjacency.corners[c] % 3;
        const Face& t = faces[f];
        const Vec3 &p0 = points[t[0]], &p1 = points[t[1]], &p2 = points[t[2]];
        const Vec3 normal = (p1 - p0).cross(p2 - p0);
        const double len = normal.norm();
        if (!(len > 0.0)) continue;
        const Vec3 opposite = points[t[(k + 2) % 3]] - points[t[(k + 1) % 3]];
        sum += 0.5 * (normal / len).cross(opposite).dot(x[f]);
      }
      b[v] = sum;
    }
  });
  return b;
}

HeatDistanceSolver::HeatDistanceSolver(const TriangleMesh& mesh, const HeatDistanceOptions& options,
                                       Progress& progress)
    : impl_(std::make_unique<Impl>())
{
  impl_->options = options;
  impl_->build(mesh, progress);
}

HeatDistanceSolver::HeatDistanceSolver(const TriangleMesh& mesh, const HeatDistanceOptions& options)
    : HeatDistanceSolver(mesh, options, silentProgress())
{
}

HeatDistanceSolver::~HeatDistanceSolver() = default;
double HeatDistanceSolver::meanEdgeLength() const
{
  return impl_->h;
}
double HeatDistanceSolver::heatTime() const
{
  return impl_->time;
}
const HeatDistanceStats& HeatDistanceSolver::lastStats() const
{
  return impl_->stats;
}
const HeatDistanceSetupStats& HeatDistanceSolver::setupStats() const
{
  return impl_->setup;
}

std::vector<double> HeatDistanceSolver::compute(const std::vector<int>& sources)
{
  NullProgress none;
  return compute(sources, none);
}

std::vector<double> HeatDistanceSolver::compute(const std::vector<int>& sources, Progress& progress)
{
  const auto start = std::chrono::steady_clock::now();
  Impl& m = *impl_;
  const int n = int(m.points.size());
  if (sources.empty())
    throw InputError("no source vertices for the geodesic distance",
                     "pass the vertices of the lower boundary");
  for (int s : sources)
    if (s < 0 || s >= n)
      throw InputError("source vertex " + std::to_string(s) + " does not exist (the mesh has " +
                           std::to_string(n) + " vertices)",
                       "pass vertex ids of this mesh");

  progress.report(0.0, "field: heat flow");
  const std::vector<double> u = m.heatSolve(sources);
  progress.checkCancel();
  progress.report(0.4, "field: divergence");
  std::vector<double> phi = m.poissonFactor->solve(m.divergence(m.unitDescent(u, m.stats.facesWithoutHeat)));
  progress.checkCancel();
  // Each refinement takes its directions from phi instead of u: the heat step's directions
  // scatter on irregular triangles, and since only their mean flux reaches phi, the scatter
  // shortens every distance (about 0.2 % at a jitter of 0.2 edges). phi is smooth, so its
  // directions scatter far less; faces where it is flat keep no direction, as for u.
  for (int k = 0; k < m.options.refinementSteps; ++k) {
    progress.report(0.6 + 0.3 * k / m.options.refinementSteps, "field: refining");
    for (double& value : phi) value = -value;
    int flat = 0;
    phi = m.poissonFactor->solve(m.divergence(m.unitDescent(phi, flat)));
    progress.checkCancel();
  }

  // The sources are all at distance 0, but phi is known only up to a constant per component:
  // the least-squares constant, the mean over the component's sources, is used. The smallest
  // value would follow the single worst source vertex (a seam of the base loop) and lift the
  // whole field by that vertex's error. Sources without a usable face hold no value of phi.
  // A component with no source is unreachable.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> shift(m.adjacency.componentCount, 0.0);
  std::vector<int> count(m.adjacency.componentCount, 0);
  std::vector<char> reached(m.adjacency.componentCount, 0);
  for (int s : sources) {
    const int c = m.adjacency.component[s];
    reached[c] = 1;
    if (m.isolated[s]) continue;
    shift[c] += phi[s];
    ++count[c];
  }
  for (int v = 0; v < n; ++v) {
    const int c = m.adjacency.component[v];
    phi[v] = !reached[c] ? inf : count[c] > 0 ? phi[v] - shift[c] / count[c] : phi[v];
  }
  m.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.report(1.0, "field: distance");
  return phi;
}

std::vector<double> heatGeodesicDistance(const TriangleMesh& mesh, const std::vector<int>& sources,
                                         const HeatDistanceOptions& options, Progress& progress)
{
  SubProgress setup(progress, 0.0, 0.8, "field: factorising");
  HeatDistanceSolver solver(mesh, options, setup);
  SubProgress solve(progress, 0.8, 1.0, "field: solving");
  return solver.compute(sources, solve);
}

std::vector<double> heatGeodesicDistance(const TriangleMesh& mesh, const std::vector<int>& sources,
                                         const HeatDistanceOptions& options)
{
  NullProgress none;
  return heatGeodesicDistance(mesh, sources, options, none);
}

}  // namespace spira
