// The coverage check and fill-in (thesis Eq. 3.8-3.9), measured against the analytic surface.
#include <gtest/gtest.h>

#include <cmath>

#include "decomposer_geodesic/geodesic_decomposition.h"
#include "geodesic_shapes.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira::test {
namespace {

using geodesic::decomposeByGeodesics;
using geodesic::GeodesicDecomposition;
using geodesic::GeodesicOptions;

GeodesicDecomposition decompose(const Part& part, size_t n, double tolerance, int rounds)
{
  GeodesicOptions options;
  options.pointsPerRevolution = n;
  options.coverageTolerance = tolerance;
  options.fillRounds = rounds;
  NullProgress progress;
  const DecomposeInput in = part.input();
  return decomposeByGeodesics(part.mesh, in.lower, in.upper ? &*in.upper : nullptr, std::nullopt, nullptr,
                              options, progress);
}

// Eq. 3.9 measured independently: the largest distance from a rung midpoint (the strip between
// neighbouring generatrices) to the analytic surface.
double stripGap(const Generatrices& g, const std::function<double(double, double)>& radius)
{
  double worst = 0.0;
  for (size_t i = 0; i < g.lines.size(); ++i) {
    const auto& a = g.lines[i];
    const auto& b = g.lines[(i + 1) % g.lines.size()];
    for (size_t k = 0; k < a.size(); ++k)
      worst = std::max(worst, distanceToTube(0.5 * (a[k] + b[k]), radius));
  }
  return worst;
}

TEST(GeodesicCoverage, EightGeneratricesOnACylinderAreFilledUntilTheGapIsUnderTheTolerance)
{
  const double R = 50.0, H = 40.0, tolerance = 0.5;
  const Part part = makePart(makeOpenCylinder(R, H, 256, 20));
  auto cylinder = [&](double, double) { return R; };

  // Without fill-in, the strip between generatrices 45 degrees apart cuts R (1 - cos 22.5 deg) deep.
  const GeodesicDecomposition bare = decompose(part, 8, tolerance, 0);
  ASSERT_EQ(bare.generatrices.lines.size(), 8u);
  EXPECT_NEAR(stripGap(bare.generatrices, cylinder), R * (1.0 - std::cos(kPi / 8.0)), 0.02);
  EXPECT_NEAR(bare.stats.coverageError, R * (1.0 - std::cos(kPi / 8.0)), 0.02);
  ASSERT_FALSE(bare.warnings.empty());
  EXPECT_NE(bare.warnings.back().find("coverage error"), std::string::npos) << bare.warnings.back();

  // 16 generatrices still leave 0.96 mm, 32 leave 0.24 mm: two rounds, 24 fill-ins.
  const GeodesicDecomposition filled = decompose(part, 8, tolerance, 6);
  ASSERT_EQ(filled.generatrices.lines.size(), 32u);
  EXPECT_EQ(filled.stats.fillIns, 24u);
  EXPECT_EQ(filled.stats.fillRounds, 2);
  const double gap = stripGap(filled.generatrices, cylinder);
  EXPECT_LT(gap, tolerance);
  EXPECT_NEAR(gap, R * (1.0 - std::cos(kPi / 32.0)), 0.02);
  EXPECT_LT(filled.stats.coverageError, tolerance);
  // The fill-ins sit halfway between their neighbours and climb the full height.
  for (size_t i = 0; i < 32; ++i) {
    SCOPED_TRACE(i);
    const auto& line = filled.generatrices.lines[i];
    EXPECT_EQ(filled.fillIn[i], i % 4 != 0);
    EXPECT_NEAR(angleOf(line.front()), 2.0 * kPi * double(i) / 32.0, 1e-6);
    EXPECT_NEAR(polylineLength(line), H, 0.002 * H);
    EXPECT_EQ(line.size(), filled.generatrices.lines[0].size());
    EXPECT_EQ(filled.generatrices.normals[i].size(), line.size());
  }
}

// Geodesics slip round a bump instead of climbing over it (thesis Fig. 3.21): the strip between
// the two that pass on either side runs under the bump. Fill-ins close the gap.
TEST(GeodesicCoverage, GeodesicsSkirtingABumpGetFillInsOverIt)
{
  const Bump bump{30.0, 9.0, 30.0, 0.3, 10.0};
  auto radius = [&](double a, double z) { return bump.radius(a, z); };
  const Part part = makePart(makeTube(
      radius, [](double) { return 60.0; }, 160, 60));
  const double tolerance = 0.3;

  const GeodesicDecomposition bare = decompose(part, 24, tolerance, 0);
  const double bareGap = stripGap(bare.generatrices, radius);
  EXPECT_GT(bareGap, 3.0 * tolerance);

  const GeodesicDecomposition filled = decompose(part, 24, tolerance, 6);
  EXPECT_GT(filled.stats.fillIns, 0u);
  EXPECT_LT(filled.stats.coverageError, tolerance);
  EXPECT_LT(stripGap(filled.generatrices, radius), tolerance + 0.05);  // + the mesh's chordal error
  // Still one loop around the part: base angles increase all the way round.
  const auto& lines = filled.generatrices.lines;
  for (size_t i = 1; i < lines.size(); ++i)
    EXPECT_GT(angleOf(lines[i].front()), angleOf(lines[i - 1].front()));
}

}  // namespace
}  // namespace spira::test
