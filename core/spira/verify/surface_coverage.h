#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/verify/segment_grid.h"

namespace spira {

struct SurfaceCoverage {
  double area = 0.0, uncoveredArea = 0.0;  // mm^2
  double largestGap = 0.0;                 // mm, from the surface to the nearest segment
  Vec3 largestGapAt = Vec3::Zero();
};

// The first beads' footprint on the substrate: a sample on the plane z (within `tolerance`) is
// covered where a segment no higher than `height` above it passes within `halfWidth` of it
// horizontally (the base face of a thin-walled solid's bottom, wider than the ball of `radius`).
struct SubstrateFootprint {
  double z = 0.0, halfWidth = 0.0, height = 0.0, tolerance = 0.0;
};

// Samples every triangle at the centroids of a k x k split no coarser than `spacing` (k >= 1) and
// counts a sample covered when a segment of `grid` passes within `radius` of it, or lies on the
// substrate inside `footprint`. The largest gap is searched up to 64 grid cells away, over at most a
// few thousand of the uncovered samples.
SurfaceCoverage measureCoverage(const TriangleMesh& surface, const std::vector<Vec3>& points,
                                const SegmentGrid& grid, double radius, double spacing,
                                const SubstrateFootprint& footprint, Progress& progress);

}  // namespace spira
