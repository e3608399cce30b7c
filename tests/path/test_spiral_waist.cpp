#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "path/analytic_generatrices.h"
#include "path/spiral_window.h"
#include "spira/base/progress.h"
#include "spira/path/spiral_builder.h"
#include "spira/verify/deposit_check.h"

namespace spira::test {
namespace {

constexpr double kRadius = 17.15;
constexpr double kBend = 6.2;   // the wall starts leaning in here, inside the fourth start-up ramp
constexpr double kNeck = 11.2;  // and stands upright again from here
constexpr double kLeanDegrees = 19.0;

// An open tube 71 mm tall, 360 generatrices, whose wall leans in by 19 degrees between z = 6.2 and
// 11.2 mm: the waist of the real straight tube in the corpus (tube_straight_wall.stl). Its normals
// are the upright tube's (radial), as that tube's are: its mesh's normals, interpolated over
// triangles 10 mm tall, hardly turn with the waist, so the build direction stays within a few
// degrees of vertical and the ramps' steps, which follow the wall, lean on it by up to 19 degrees.
Generatrices waistedTube()
{
  const double slope = std::tan(kLeanDegrees * kPi / 180.0);
  return radialLines(360, 711, [slope](int, double a, int k) {
    const double z = 0.1 * k;  // the bends are vertices
    const double r = kRadius - slope * std::clamp(z - kBend, 0.0, kNeck - kBend);
    return Vec3(r * std::cos(a), r * std::sin(a), z);
  });
}

// The fourth full start-up ramp climbs from z = 7.2 to 8.8 mm around its revolution, into the
// waist: the stretch its steps need grows from about 1.02 on its first generatrices, whose 1.8 mm
// steps cross the bend, to 1.06 on its last. Ramp scales limited around the revolution as a circle
// hold the last ones down towards the first, so the path dips over its last generatrices (0.02 mm)
// and tilts their frames; scales smoothed across the seam pull the previous revolution's last
// generatrices (h_max steps below the bend) up and the next one's first down (planned 2.213 and
// 1.789 mm). The deposit check reads the plan's positions and frames only.
TEST(SpiralWaist, StartUpIntoAWaistNeitherDipsNorLeavesTheWindowAtItsSeams)
{
  const Generatrices g = waistedTube();
  const SpiralSettings s = test::thesisWindow();
  NullProgress progress;
  const SpiralResult r = buildSpiral(g, s, progress);
  ASSERT_EQ(r.report.nStartupRevolutions, 6);
  EXPECT_TRUE(r.report.violations.empty())
      << r.report.violations.size() << " planned deposits outside the window";
  const auto& t = r.trajectory.points;
  const size_t n = g.lines.size();
  for (int rev = 0; rev < r.report.nStartupRevolutions; ++rev)
    for (size_t i = n - 8; i < n; ++i) {
      const size_t q = rev * n + i;
      EXPECT_GT(t[q].position.z(), t[q - 1].position.z()) << "revolution " << rev << ", generatrix " << i;
    }
  DepositCheckSettings c;
  c.hMin = s.hMin;
  c.hMax = s.hMax;
  const DepositCheckReport check = checkDeposits(r.trajectory, nullptr, c, progress);
  EXPECT_EQ(check.count(DepositDefect::Thick), 0u) << check.summary();
  EXPECT_LE(check.heightMax, s.hMax + c.tolerance);
}

}  // namespace
}  // namespace spira::test
