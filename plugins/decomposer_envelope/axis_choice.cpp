#include "axis_choice.h"

#include <algorithm>

#include "skeleton_fit.h"
#include "spira/base/error.h"
#include "spira/skeleton/mcf_skeleton.h"

namespace spira {

namespace {

const std::string kIsovalueHint = "use the iso-value strategy (--strategy isovalue), which needs no skeleton";

}  // namespace

AxisChoice chooseProjectionAxis(const TriangleMesh& mesh, const BoundaryLoop& lower, AxisMode mode,
                                Progress& progress)
{
  const Vec3 centroid = loopCentroid(mesh, lower);
  AxisChoice out;
  if (mode == AxisMode::Vertical) {
    out.axis = ProjectionAxis::vertical(centroid);
    out.source = "the vertical axis through the base centroid";
    return out;
  }

  const SkeletonResult result = computeCurveSkeleton(mesh, SkeletonOptions{}, progress);
  out.warnings = result.warnings;
  const CurveSkeleton& s = result.skeleton;
  if (!s.monoBranch())
    throw InputError("the part's skeleton has " + std::to_string(s.branchCount()) + " branches, " +
                         std::to_string(s.branchPoints.size()) + " branch points and " +
                         std::to_string(s.loops) +
                         " loops; envelope projection needs a single chain (a mono-branch part)",
                     "split the part into mono-branch pieces, or " + kIsovalueHint);
  if (!s.monotoneInZ)
    throw InputError(
        "the part's skeleton does not rise steadily in z, so there is no single skeleton point "
        "per height to project towards",
        kIsovalueHint + ", or --axis vertical for a part of revolution");
  double radius = 0.0;
  for (int v : lower.vertices) {
    const Vec3 d = mesh.vertices[v] - centroid;
    radius += std::hypot(d.x(), d.y());
  }
  radius /= static_cast<double>(std::max<size_t>(1, lower.vertices.size()));
  // Each local fit spans the part's diameter in height: wide enough to average the nodes' jitter
  // out, short enough to follow a skeleton that bends over a few diameters.
  const HeightFit fit = fitChainByHeight(s.branches.front(), radius);
  if (mode == AxisMode::Skeleton) {
    out.axis = ProjectionAxis::chain(fit.points);
    out.source = "the skeleton";
    return out;
  }

  double z0 = mesh.vertices.empty() ? 0.0 : mesh.vertices.front().z(), z1 = z0;
  for (const Vec3& v : mesh.vertices) {
    z0 = std::min(z0, v.z());
    z1 = std::max(z1, v.z());
  }
  const double tolerance = 0.05 * radius;
  if (largestOffsetFromVertical(fit, centroid, z0, z1) <= tolerance) {
    out.axis = ProjectionAxis::vertical(centroid);
    out.source = "the vertical axis through the base centroid (the skeleton runs along it)";
  } else if (largestOffsetFromLine(fit) <= tolerance) {
    out.axis = ProjectionAxis::line(fit.points.front(), fit.points.back());
    out.source = "the straight skeleton";
  } else {
    out.axis = ProjectionAxis::chain(fit.points);
    out.source = "the skeleton";
  }
  return out;
}

}  // namespace spira
