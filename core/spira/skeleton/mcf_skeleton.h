#pragma once

#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/skeleton/curve_skeleton.h"

namespace spira {

struct SkeletonOptions {
  // Contraction steps at most. Each step solves one sparse least-squares system; a part of a few
  // thousand faces converges in 20 to 60 steps.
  size_t maxIterations = 150;
  // Converged when one step changes the meso-skeleton's area by less than this fraction of the
  // original area (CGAL's default).
  double areaVariation = 1e-4;
  // Pull towards the medial axis (Voronoi poles) as well as along the flow: the skeleton then
  // runs through the middle of the part instead of wherever the flow happens to collapse.
  bool mediallyCentered = true;
  double qualitySpeedTradeoff = 0.1;  // CGAL's omega_H: higher keeps the mesh nearer its shape
  double medialSpeedTradeoff = 0.2;   // CGAL's omega_P: higher pulls harder towards the medial axis
  // Largest z fall (mm) along a single chain still called monotone; < 0 picks 2 % of the part's
  // bounding-box diagonal. The contraction leaves a few nodes out of order, by up to 0.95 % of the
  // diagonal on an upright cone.
  double monotoneTolerance = -1.0;
  // Surfaces with more faces are simplified (edge collapse) to about this many before the flow;
  // 0 keeps every face. The flow's cost grows faster than the face count, and the curve it ends
  // in does not need the full resolution.
  size_t maxFaces = 6000;
  // Remove terminal branches shorter than the part's radius at their branch point (see
  // skeleton_pruning.h): wrinkles of the contraction, not limbs of the part.
  bool pruneSpurs = true;
  // Move chain nodes to the centroid of the part's cross-section through them (see
  // skeleton_centering.h); off leaves them where the flow put them.
  bool centreInSections = true;
};

struct SkeletonResult {
  CurveSkeleton skeleton;
  size_t iterations = 0;       // contraction steps run
  bool converged = false;      // the area settled before maxIterations
  size_t capsAdded = 0;        // boundary loops capped for the contraction (open parts)
  size_t facesContracted = 0;  // faces of the (capped) surface given to the flow
  size_t spursPruned = 0;      // short terminal branches removed
  size_t nodesCentred = 0;     // nodes moved to their cross-section's centroid
  std::vector<std::string> warnings;
};

// The mean curvature flow curve skeleton (Tagliasacchi et al. 2012, CGAL's implementation), the
// thesis's topology check (000_dbb97c2716e10cc3.txt §3.3.1). Open parts are capped first (see
// capped_surface.h): the flow needs a closed surface. The skeleton is in the part's frame.
//
// Throws InputError, saying what is wrong and what to do, for an empty mesh, several components,
// non-manifold or inconsistently oriented meshes and free edges that do not close into loops;
// AlgorithmError when the flow leaves no skeleton. Reaching maxIterations is a warning.
// Honours cancellation between contraction steps.
SkeletonResult computeCurveSkeleton(const TriangleMesh& mesh, const SkeletonOptions& options,
                                    Progress& progress);

}  // namespace spira
