// A bent tube's guide curve found automatically (issue 18): the curve skeleton of the part is its
// centre line, and layers at a constant distance follow it on the part's own facets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "spira/base/progress.h"
#include "spira/contour/constant_distance.h"
#include "spira/contour/guided_tube.h"
#include "spira/contour/meshed_tube.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/skeleton/mcf_skeleton.h"

namespace spira {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(TubeGuide, SkeletonOfABentTubeIsItsCentreLineAndGuidesTheLayers)
{
  const double R = 50.0, r = 15.0;
  const TriangleMesh tube = makeBentTube(R, r, 0.5 * kPi, 72, 60);
  NullProgress progress;
  const SkeletonResult s = computeCurveSkeleton(tube, SkeletonOptions{}, progress);
  ASSERT_TRUE(s.skeleton.monoBranch());
  ASSERT_EQ(s.skeleton.branchCount(), 1u);
  Polyline line = s.skeleton.branches[0];
  ASSERT_GE(line.size(), 10u);
  if (line.front().z() > line.back().z()) std::reverse(line.begin(), line.end());
  // On the arc of radius R about (-R, 0, 0) in y = 0, from the base centre to the top one.
  double off = 0.0;
  for (const Vec3& p : line) off = std::max(off, std::hypot(std::hypot(p.x() + R, p.z()) - R, p.y()));
  EXPECT_LT(off, 1.0);
  // The flow's curve stops short of the open ends (by 8 and 11 mm here, under r): the guide runs on
  // straight past them, and the first layer is taken on the tube's base edge.
  EXPECT_LT(line.front().norm(), r);
  EXPECT_LT((line.back() - Vec3(-R, 0.0, R)).norm(), r);

  double length = 0.0;
  for (size_t k = 1; k < line.size(); ++k) length += (line[k] - line[k - 1]).norm();
  const auto guide = polylineGuide(line);
  const TubeSurface surface = meshedTube(tube, guide, -2.0 * r, length + 2.0 * r, 3.0 * r);
  ConstantDistanceSettings settings;
  settings.delta = 5.0;
  settings.pointsPerLayer = 180;
  // The inner wall (35 mm from the bend's axis against 50 for the guide) runs ahead and leaves the mesh
  // at its top first: without a surface past the end, the layers stop while the inner side is on it.
  const ConstantDistanceLayers layers =
      constantDistanceLayers(surface, baseLayer(surface, 180, -2.0 * r, r), 0.45 * length, settings);
  ASSERT_TRUE(layers.complete);
  double worst = 0.0;
  for (size_t n = 1; n < layers.points.size(); ++n)
    for (const Vec3& p : layers.points[n])
      worst = std::max(worst, std::abs(distanceToClosedLayer(p, layers.points[n - 1], 0, 0) - 5.0));
  EXPECT_LT(worst, 1e-3);
  std::printf(
      "bent tube skeleton: %zu points, %.2f mm off the arc at worst, %.1f mm long (arc %.1f); %zu layers at "
      "5 mm to 45 %% of it\n",
      line.size(), off, length, 0.5 * kPi * R, layers.t.size() - 1);
}

}  // namespace
}  // namespace spira
