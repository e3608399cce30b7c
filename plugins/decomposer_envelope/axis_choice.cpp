#include "axis_choice.h"

#include <algorithm>

#include "spira/base/error.h"
#include "spira/skeleton/mcf_skeleton.h"

namespace spira {

namespace {

double distanceToLine(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 d = (b - a).normalized();
  const Vec3 r = p - a;
  return (r - r.dot(d) * d).norm();
}

double largestDistance(const Polyline& points, const Vec3& a, const Vec3& b)
{
  double worst = 0.0;
  for (const Vec3& p : points) worst = std::max(worst, distanceToLine(p, a, b));
  return worst;
}

const std::string kIsovalueHint = "use the iso-value strategy (decomposer.isovalue), which needs no skeleton";

}  // namespace

Vec3 loopCentroid(const TriangleMesh& mesh, const BoundaryLoop& loop)
{
  Vec3 sum = Vec3::Zero();
  double length = 0.0;
  const size_t n = loop.vertices.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = mesh.vertices[loop.vertices[i]];
    const Vec3& b = mesh.vertices[loop.vertices[(i + 1) % n]];
    const double l = (b - a).norm();
    sum += l * 0.5 * (a + b);
    length += l;
  }
  if (length > 0) return sum / length;
  for (int v : loop.vertices) sum += mesh.vertices[v];
  return n ? Vec3(sum / static_cast<double>(n)) : Vec3::Zero();
}

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
        kIsovalueHint + ", or choose axis = vertical for a part of revolution");
  const Polyline& chain = s.branches.front();
  if (mode == AxisMode::Skeleton) {
    out.axis = ProjectionAxis::chain(chain);
    out.source = "the skeleton";
    return out;
  }

  double radius = 0.0;
  for (int v : lower.vertices) {
    const Vec3 d = mesh.vertices[v] - centroid;
    radius += std::hypot(d.x(), d.y());
  }
  radius /= static_cast<double>(std::max<size_t>(1, lower.vertices.size()));
  const double tolerance = 0.05 * radius;
  if (largestDistance(chain, centroid, centroid + Vec3::UnitZ()) <= tolerance) {
    out.axis = ProjectionAxis::vertical(centroid);
    out.source = "the vertical axis through the base centroid (the skeleton runs along it)";
  } else if (largestDistance(chain, chain.front(), chain.back()) <= tolerance) {
    out.axis = ProjectionAxis::line(chain.front(), chain.back());
    out.source = "the straight skeleton";
  } else {
    out.axis = ProjectionAxis::chain(chain);
    out.source = "the skeleton";
  }
  return out;
}

}  // namespace spira
