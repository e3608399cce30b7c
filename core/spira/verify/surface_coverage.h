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

// Samples every triangle at the centroids of a k x k split no coarser than `spacing` (k >= 1) and
// counts a sample covered when a segment of `grid` passes within `radius` of it. The largest gap is
// searched up to 64 grid cells away, over at most a few thousand of the uncovered samples.
SurfaceCoverage measureCoverage(const TriangleMesh& surface, const std::vector<Vec3>& points,
                                const SegmentGrid& grid, double radius, double spacing, Progress& progress);

}  // namespace spira
