// Geodesics that run exactly along mesh edges: on a cylinder meshed with as many segments as
// there are generatrices, every base point is a vertex and its geodesic is the vertical edge line.
#include <gtest/gtest.h>

#include "decomposer_geodesic/geodesic_decomposition.h"
#include "geodesic_shapes.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira::test {
namespace {

TEST(GeodesicEdgePaths, AGeneratrixAlongAMeshEdgeIsTheStraightEdgeLine)
{
  const double R = 30.0, H = 60.0;
  const Part part = makePart(makeOpenCylinder(R, H, 96, 40));
  geodesic::GeodesicOptions options;
  options.pointsPerRevolution = 96;
  NullProgress progress;
  const DecomposeInput in = part.input();
  const geodesic::GeodesicDecomposition d = geodesic::decomposeByGeodesics(
      part.mesh, in.lower, in.upper ? &*in.upper : nullptr, std::nullopt, nullptr, options, progress);
  ASSERT_EQ(d.generatrices.lines.size(), 96u);
  EXPECT_EQ(d.stats.fillIns, 0u);
  EXPECT_LT(d.stats.coverageError, options.coverageTolerance);
  for (size_t i = 0; i < d.generatrices.lines.size(); ++i) {
    SCOPED_TRACE(i);
    const Polyline& line = d.generatrices.lines[i];
    EXPECT_NEAR(d.exactLengths[i], H, 1e-6 * H);
    EXPECT_NEAR(polylineLength(line), H, 1e-6 * H);
    // Every point on the vertical line above the base point (to a micrometre), not on the next
    // edge line 2 mm away.
    for (const Vec3& p : line)
      EXPECT_LT(std::hypot(p.x() - line.front().x(), p.y() - line.front().y()), 1e-3);
  }
}

}  // namespace
}  // namespace spira::test
