#include <gtest/gtest.h>

#include <cmath>

#include "planning/slanted_tube.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/planar_baseline.h"

namespace spira {
namespace {

PlanarBaseline slice(const TriangleMesh& m, double h = 2.0)
{
  const MeshReport r = validateMesh(m);
  PlanarBaselineSettings s;
  s.h = h;
  s.hMin = 0.9 * h;
  s.hMax = 1.1 * h;
  s.tolerance = 0.005 * h;
  NullProgress progress;
  return planarBaseline(m, r, 0, s, progress);  // loops sorted by zMin: 0 is the base
}

// Vertical walls: every layer lies exactly h above the one below, the top edge too.
TEST(PlanarBaseline, VerticalTubeGetsTheNominalHeightEverywhere)
{
  const PlanarBaseline b = slice(makeOpenCylinder(40.0, 100.0, 120, 25));
  EXPECT_EQ(b.layers, 50);  // planes z = 2 .. 98, then the top edge at 100
  EXPECT_NEAR(b.heightMin, 2.0, 1e-9);
  EXPECT_NEAR(b.heightMax, 2.0, 1e-9);
  EXPECT_EQ(b.outside, 0u);
  EXPECT_TRUE(b.feasible());
}

// A wall leaning by beta: consecutive planes are h / cos(beta) apart along it. At tan(beta) = 1/2
// that is 2.236 mm, outside 2 mm +/- 10 %: the 2.5D baseline fails where CTPP, which steps along
// the wall, would lay 2 mm.
TEST(PlanarBaseline, LeaningWallsGetHOverCosBeta)
{
  const double r0 = 40.0, r1 = 10.0, height = 60.0;
  const PlanarBaseline b = slice(makeOpenCone(r0, r1, height, 360, 30));
  const double expected = 2.0 * std::sqrt(1.0 + std::pow((r0 - r1) / height, 2));
  EXPECT_NEAR(b.heightMin, expected, 1e-3);
  EXPECT_NEAR(b.heightMax, expected, 1e-3);
  EXPECT_EQ(b.outside, b.points.size());
  EXPECT_FALSE(b.feasible());
}

// A top edge at z = H + s cos(a): the planes stop below it, and it lies anywhere from 0 to h above
// the highest plane under it.
TEST(PlanarBaseline, ANonPlanarTopEdgeCannotBeReached)
{
  const int segments = 120;
  const TriangleMesh m = test::slantedTube(40.0, 100.0, 5.0, segments, 60);
  const PlanarBaseline b = slice(m);
  size_t edgePoints = 0;
  for (const PlanarPoint& p : b.points) {
    if (p.layer != b.layers) continue;
    ++edgePoints;
    // Straight above the highest plane under it, on a vertical wall.
    const double above = p.position.z() - 2.0 * std::floor(p.position.z() / 2.0 - 1e-12);
    EXPECT_NEAR(p.height, above, 1e-6) << p.position.transpose();
  }
  EXPECT_EQ(edgePoints, static_cast<size_t>(segments));
  EXPECT_LT(b.heightMin, 0.5);
  EXPECT_GT(b.outside, 0u);
  EXPECT_FALSE(b.feasible());
}

TEST(PlanarBaseline, RefusesAPartShorterThanALayer)
{
  EXPECT_THROW(slice(makeOpenCylinder(40.0, 1.5, 60, 2)), InputError);
  EXPECT_THROW(slice(makeOpenCylinder(40.0, 10.0, 60, 2), 0.0), InputError);
}

}  // namespace
}  // namespace spira
