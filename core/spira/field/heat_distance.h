#pragma once

#include <memory>
#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

struct HeatDistanceOptions {
  // Heat time t = timeScale * h^2 with h the mean edge length (thesis Appendix A.1: 1).
  double timeScale = 1.0;
  // On free edges that are not sources, average the Neumann solution and the Dirichlet
  // solution (u = 0 there), which makes the distance behave as if the boundary were not there
  // (Crane et al. 2013; thesis 000_dbb97c2716e10cc3.txt §3.3.2.3). False keeps the Neumann solution alone, as
  // CGAL does.
  bool averageBoundaryConditions = true;
  // Poisson solves after the first, each with the unit directions of the previous distance
  // instead of those of the heat flow. Each costs one pass over the faces and one solve with
  // the factor already computed; 0 is the plain heat method.
  int refinementSteps = 1;
};

// What the last compute() did, for reports and benchmarks.
struct HeatDistanceStats {
  bool usedDirichlet = false;  // a second heat solve with u = 0 on the free, non-source vertices
  int dirichletVertices = 0;
  int facesWithoutHeat = 0;  // faces where u underflowed to 0: their direction comes from the Poisson step
  double seconds = 0.0;
};

// What the constructor did: where the set-up time went and how large the factors are.
struct HeatDistanceSetupStats {
  double operatorSeconds = 0.0;  // adjacency, cotan Laplacian, areas, the system matrices
  double analysisSeconds = 0.0;  // fill-reducing order and symbolic analysis
  double factorSeconds = 0.0;    // the heat and Poisson factorisations (run concurrently)
  double factorNonZeros = 0.0;   // entries of one Cholesky factor
};

// Geodesic distance by the heat method (Crane, Weischedel & Wardetzky 2013; thesis 000_dbb97c2716e10cc3.txt
// §3.3.2.3 and Appendix A): one heat step (A - t L_C) u = delta_sources, the unit field X = -grad u / |grad
// u| per face, its integrated divergence b, and the Poisson equation L_C phi = b; then `refinementSteps` more
// Poisson solves with X = grad phi / |grad phi|, and a shift so that the mean of phi over the sources is 0.
//
// The constructor does everything that depends on the mesh only: cotan operators, a
// fill-reducing order, one symbolic analysis and the Cholesky factorisations of the heat and
// Poisson operators (computed concurrently). compute() then costs a few triangular solves and
// two passes over the faces for any source set, so the closure search can call it often.
// The Dirichlet half of the boundary average depends on which free vertices are sources; it is
// factorised on first use and kept while the set of free non-source vertices stays the same.
//
// Not thread-safe: one compute() at a time per solver (it uses all cores itself).
class HeatDistanceSolver {
 public:
  HeatDistanceSolver(const TriangleMesh& mesh, const HeatDistanceOptions& options, Progress& progress);
  explicit HeatDistanceSolver(const TriangleMesh& mesh, const HeatDistanceOptions& options = {});
  ~HeatDistanceSolver();
  HeatDistanceSolver(const HeatDistanceSolver&) = delete;
  HeatDistanceSolver& operator=(const HeatDistanceSolver&) = delete;

  // Distance (mm) from the nearest vertex of `sources`, taken as ONE source set, at every vertex.
  // Vertices in parts of the mesh that no source reaches get +infinity.
  // Throws InputError if `sources` is empty or names a vertex that does not exist.
  std::vector<double> compute(const std::vector<int>& sources, Progress& progress);
  std::vector<double> compute(const std::vector<int>& sources);

  double meanEdgeLength() const;
  double heatTime() const;
  const HeatDistanceStats& lastStats() const;
  const HeatDistanceSetupStats& setupStats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One-off: builds a solver and computes once.
std::vector<double> heatGeodesicDistance(const TriangleMesh& mesh, const std::vector<int>& sources,
                                         const HeatDistanceOptions& options, Progress& progress);
std::vector<double> heatGeodesicDistance(const TriangleMesh& mesh, const std::vector<int>& sources,
                                         const HeatDistanceOptions& options = {});

}  // namespace spira
