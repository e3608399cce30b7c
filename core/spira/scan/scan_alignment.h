#pragma once

#include <cstddef>

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/scan/point_cloud.h"

namespace spira {

// Registration of a scan to the nominal part (or substrate) by point-to-plane ICP (PCL), the part's
// surface sampled with its facet normals as the target. Correspondences farther apart than the
// current distance are rejected; the distance shrinks from `startDistanceMm` to `finalDistanceMm` so
// that the first rounds pull from the initial guess and the last fit only the surface itself.
struct AlignSettings {
  double voxelMm = 1.0;  // the scan is thinned to one point per cell for the fit
  double startDistanceMm = 10.0;
  double finalDistanceMm = 1.0;
  int iterationsPerStage = 40;
  size_t minimumPoints = 100;  // fewer scan points (after thinning) are refused
  size_t fitPoints = 30000;    // at most this many of them take part in the fit
};

struct AlignResult {
  // Maps scan coordinates into the part's frame: the scan is moved, the path frame never is.
  Transform T_part_scan = Transform::Identity();
  double rmsMm = 0.0;           // point-to-surface residual of the matched points
  double inlierFraction = 0.0;  // share of the thinned scan within finalDistanceMm of the surface
  size_t pointsUsed = 0;        // thinned scan points the fit used
  int iterations = 0;
  bool converged = false;
};

// `T_initial` maps the scan into the part's frame before the fit (identity: the scan was taken in the
// part's frame, as a cell's calibrated scanner gives it). Throws InputError when the scan has too few
// points, or when after the fit under half of it lies near the part (the scan does not overlap it);
// Cancelled.
AlignResult alignScan(const PointCloud& scan, const TriangleMesh& part, const Transform& T_initial,
                      const AlignSettings& settings, Progress& progress);

// The part's surface as points with their facet's normal, about one per `spacing` mm^2 cell of area
// (at least one per facet), in a repeatable order.
PointCloud sampleSurface(const TriangleMesh& mesh, double spacing);

}  // namespace spira
