#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "path/analytic_generatrices.h"
#include "path/spiral_window.h"
#include "spira/base/progress.h"
#include "spira/path/spiral_builder.h"

namespace spira::test {
namespace {

// A cylinder of radius 12 mm (120 generatrices, 0.63 mm apart, as on a branch's arm) standing on a
// V-notched base: z_0 = 4 (1 - |phi - pi|) mm within 1 rad of phi = pi, 0 elsewhere. Its flanks rise
// 4 mm over 12 mm of wall, so the start-up's ramps lean on the vertical generatrices by
// atan(1/3) = 18.4 degrees next to the base and the ramp steps there are stretched by up to
// 1 / cos(18.4 deg) = 1.054 (docs/method.md M18).
Generatrices vNotchedCylinder()
{
  return radialLines(120, 200, [](int, double a, int k) {
    const double z0 = 4.0 * std::max(0.0, 1.0 - std::abs(a - kPi));
    return Vec3(12.0 * std::cos(a), 12.0 * std::sin(a), z0 + (100.0 - z0) * k / 199.0);
  });
}

// The unstretched ramps rise linearly with u around a revolution (second difference 0) and the
// stretch the lean asks for is constant on each flank (1.054) and on the level part (1): the rise
// above the base bends only near the V's corners and tip. A point stretched more than its
// neighbours tilts the chords (the travel direction of its frame) on both sides, which lowers their
// heights and asks for more stretch there: a point-by-point stretch grew that into an alternating
// pattern (second difference 0.33 mm between points 0.63 mm apart) that put the corners' ramp
// points down to 1.58 mm. Smoothed along the path, the rise bends by less than 0.04 mm per point.
TEST(SpiralStretch, StartUpOnALeaningBaseRisesWithoutAlternating)
{
  const Generatrices g = vNotchedCylinder();
  const SpiralSettings s = test::thesisWindow();
  NullProgress progress;
  const SpiralResult r = buildSpiral(g, s, progress);
  const auto& t = r.trajectory.points;
  const int n = static_cast<int>(g.lines.size());
  ASSERT_EQ(r.report.nStartupRevolutions, 6);
  const auto rise = [&](size_t q) { return t[q].position.z() - g.lines[t[q].generatrix].front().z(); };
  double bend = 0.0, lowest = s.h;
  for (int rev = 0; rev < r.report.nStartupRevolutions; ++rev)
    for (int i = 1; i + 1 < n; ++i) {
      const size_t q = static_cast<size_t>(rev) * n + i;
      bend = std::max(bend, std::abs(rise(q + 1) - 2.0 * rise(q) + rise(q - 1)));
      lowest = std::min(lowest, t[q].height);
    }
  EXPECT_LT(bend, 0.1);
  // Where the base's slope jumps (the V's corners) the start-up stays within 0.05 mm of h_min.
  EXPECT_GT(lowest, s.hMin - 0.05);
}

}  // namespace
}  // namespace spira::test
