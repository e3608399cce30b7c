#pragma once

#include <string>
#include <vector>

#include "projection_axis.h"
#include "spira/base/progress.h"
#include "spira/mesh/boundary_loops.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

enum class AxisMode {
  Auto,      // the skeleton; the vertical line through the base centroid when the skeleton runs along it
  Skeleton,  // the skeleton's chain (fitted by height)
  Vertical,  // the vertical line through the base centroid, no skeleton computed (fast)
};

struct AxisChoice {
  ProjectionAxis axis = ProjectionAxis::vertical(Vec3::Zero());
  std::string source;  // in words, for warnings and reports
  std::vector<std::string> warnings;
};

// The axis the envelope points are projected towards. With a skeleton (Auto, Skeleton) the part
// must be mono-branch with a skeleton rising steadily in z, else InputError says so and points
// to the iso-value strategy. The skeleton's nodes are first fitted as a smooth function of height
// (skeleton_fit.h). Auto uses the exact vertical line through the base centroid when the fitted
// skeleton, and its straight line extended over the part's height, lie within 5 % of the base
// radius of it (a part of revolution standing upright: the line is truer than any skeleton), the
// fitted straight line when the fitted skeleton lies that close to it, and the fitted chain
// otherwise.
AxisChoice chooseProjectionAxis(const TriangleMesh& mesh, const BoundaryLoop& lower, AxisMode mode,
                                Progress& progress);

}  // namespace spira
