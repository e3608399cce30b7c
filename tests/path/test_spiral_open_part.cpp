// Open parts whose generatrices differ in length: the deposit is modulated point by point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "analytic_generatrices.h"
#include "spira/base/progress.h"
#include "spira/path/feasibility.h"
#include "spira/path/spiral_builder.h"
#include "spiral_window.h"

using namespace spira;

// Thesis Table 3.3 (the "trompe", 000_dbb97c2716e10cc3.txt §3.4.1.2): generatrices of 152 to 178 mm at 2 ±
// 0.2 mm give 84 revolutions, deposits of 1.81 to 2.12 mm, feasible. Table 3.3's 84 is floor(152 / 1.8):
// Eq. 3.14 (and Eq. 3.6) applied to the lengths being divided into layers. In Spira those are the lengths
// left for the modulated phase once the start-up and termination ramps are laid, so this part's
// generatrices are 152..178 mm plus the ramps (which take the same length on every generatrix).
// The Eq. 3.6 pre-check on raw lengths 152..178 also gives 84 (LayerCount.ThesisTable33Criterion).
// The upper edge leans (up to 13/60 rad), so the termination ramps are stretched by 1 / cos(theta)
// (up to 2.4 %) to keep their true heights; that takes up to 0.3 mm more of the long generatrices
// than the unstretched ramps this part was sized for, hence the 0.3 mm tolerance.
// Lengths vary smoothly: l(phi) = 165 - 13 cos(phi), shortest at phi = 0, longest at phi = pi.
TEST(SpiralOpenPart, ThesisTable33Arithmetic)
{
  const int n = 360;
  const auto modulated = [n](int i) { return 165.0 - 13.0 * std::cos(test::angleOf(i, n)); };
  // The ramps are sized for the layer step at the seam, (l_0 + l_{n-1}) / 2 / 84.
  const double ramps = test::helixRampLength(2.0, 0.5 * (modulated(0) + modulated(n - 1)) / 84.0, n);
  const Generatrices g = test::cylinderLines(
      60.0, n, [&](int i) { return modulated(i) + ramps; }, 200);
  const SpiralSettings s = test::thesisWindow();
  NullProgress progress;
  const SpiralResult r = buildSpiral(g, s, progress);
  const SpiralReport& rep = r.report;

  EXPECT_EQ(rep.nLayers, 84);
  EXPECT_EQ(rep.nRevolutions, 6 + 84 + 6);
  EXPECT_NEAR(rep.modulatedLengthMin, 152.0, 0.3);
  EXPECT_NEAR(rep.modulatedLengthMax, 178.0, 0.3);
  EXPECT_NEAR(rep.stepMin, rep.modulatedLengthMin / 84.0, 1e-12);  // 1.8095
  EXPECT_NEAR(rep.stepMax, rep.modulatedLengthMax / 84.0, 1e-12);  // 2.1190
  EXPECT_NEAR(rep.stepMin, 1.81, 0.005);
  EXPECT_NEAR(rep.stepMax, 2.12, 0.005);
  EXPECT_NEAR(rep.lengthCriterion.stepSpread, 26.0 / 84.0, 0.004);
  EXPECT_TRUE(rep.lengthCriterion.ok);
  EXPECT_TRUE(rep.feasible);
  EXPECT_TRUE(rep.violations.empty());  // ramps included

  // Generatrix i's 84 modulated steps add up to l_i, and true heights lie in [1.8, 2.12] (Fig. 3.41b:
  // 1.8-2.1). The layers lean more towards the upper edge, so the thesis's equal steps l_i / 84 would
  // lay true heights d cos(theta) falling by 0.047 mm up a generatrix; the steps are stretched by
  // 1 / cos(theta) instead (by up to 1.4 %), and each generatrix lays one true height to 0.005 mm.
  const size_t nn = n;
  std::vector<double> climbed(nn, 0.0), lowest(nn, 1e9), highest(nn, 0.0);
  for (size_t q = 6 * nn; q < (6 + 84) * nn; ++q) {
    const TrajectoryPoint& p = r.trajectory.points[q];
    const double step = p.position.z() - r.trajectory.points[q - nn].position.z();
    ASSERT_NEAR(step, modulated(p.generatrix) / 84.0, 0.015 * 2.12) << q;
    climbed[p.generatrix] += step;
    lowest[p.generatrix] = std::min(lowest[p.generatrix], p.height);
    highest[p.generatrix] = std::max(highest[p.generatrix], p.height);
    EXPECT_LE(p.height, step + 1e-12);
    EXPECT_GT(p.height, 1.8);
    EXPECT_LT(p.height, 2.12);
  }
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(climbed[i], modulated(i), 0.3) << i;
    EXPECT_LT(highest[i] - lowest[i], 0.005) << i;
  }
  // Thick where the edge is high, thin where it is low, from the first modulated revolution on.
  EXPECT_GT(r.trajectory.points[6 * nn + n / 2].height, r.trajectory.points[6 * nn].height + 0.3);
  // The last revolution lies on the (non-planar) upper edge.
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(r.trajectory.points[r.trajectory.size() - nn + i].position.z(), g.lines[i].back().z(), 1e-9);
}

// Lengths 100..130 mm for a 1 mm ± 10 % window: floor mode gives n_layer = floor(100 / 0.9) = 111
// and the long generatrices need more than h_max. The radius is large (2 m) so cos(theta) stays
// within 4e-5 of 1 and the violations follow from the lengths alone: generatrix i violates on every
// modulated revolution when l_i / 111 > h_max + 0.5 % h.
TEST(SpiralOpenPart, TooDifferentGeneratricesAreInfeasibleWithEveryViolationListed)
{
  const int n = 360;
  const auto modulated = [n](int i) { return 100.0 + 15.0 * (1.0 - std::cos(test::angleOf(i, n))); };
  const int nLayers = 111;
  const double ramps = test::helixRampLength(1.0, 0.5 * (modulated(0) + modulated(n - 1)) / nLayers, n);
  const Generatrices g = test::cylinderLines(
      2000.0, n, [&](int i) { return modulated(i) + ramps; }, 50);
  SpiralSettings s;
  s.h = 1.0;
  s.hMin = 0.9;
  s.hMax = 1.1;
  s.layerMode = LayerMode::Floor;  // n = floor(min L / h_min): the long generatrices leave the window
  const double limit = 1.1 + 0.005;
  std::vector<int> violating;
  for (int i = 0; i < n; ++i) {
    const double d = modulated(i) / nLayers;
    ASSERT_GT(std::abs(d - limit), 1e-4) << "the count would hang on cos(theta) at generatrix " << i;
    if (d > limit) violating.push_back(i);
  }
  ASSERT_FALSE(violating.empty());

  NullProgress progress;
  const SpiralResult r = buildSpiral(g, s, progress);
  ASSERT_EQ(r.report.nLayers, nLayers);
  EXPECT_FALSE(r.report.feasible);
  EXPECT_FALSE(r.report.lengthCriterion.ok);  // 30 / 111 = 0.27 > 0.2
  EXPECT_EQ(r.report.modulatedViolations, violating.size() * nLayers);
  EXPECT_EQ(r.report.violations.size(), violating.size() * nLayers);
  for (const HeightViolation& v : r.report.violations) {
    EXPECT_TRUE(v.aboveWindow);
    EXPECT_EQ(v.phase, SpiralPhase::Modulated);
    EXPECT_TRUE(std::binary_search(violating.begin(), violating.end(), v.generatrix)) << v.generatrix;
    EXPECT_EQ(r.trajectory.points[v.point].generatrix, v.generatrix);
    EXPECT_EQ(r.trajectory.points[v.point].height, v.height);
    EXPECT_NEAR(v.height, modulated(v.generatrix) / nLayers, 1e-4);
  }
  EXPECT_GT(r.report.heightMax, 1.1);
  // The plan still exists: infeasibility is a report, not an exception.
  EXPECT_EQ(r.trajectory.size(), static_cast<size_t>(r.report.nRevolutions) * n);
}

// A slanted part (cone frustum): frames are orthonormal, b points up the generatrices, and the height
// channel equals d cos(theta) recomputed from the positions and b (straight generatrices: d = |v|).
TEST(SpiralOpenPart, ConeFramesAndHeightsFromPositions)
{
  const int n = 180;
  const Generatrices g = test::coneLines(40.0, 25.0, 60.0, n, 30);
  SpiralSettings s;
  s.h = 1.5;
  s.hMin = 1.35;
  s.hMax = 1.65;
  s.layerMode = LayerMode::Centered;
  NullProgress progress;
  const SpiralResult r = buildSpiral(g, s, progress);
  const Trajectory& t = r.trajectory;
  const Vec3 up = (g.lines[0].back() - g.lines[0].front()).normalized();
  const double slant = std::hypot(60.0, 15.0);
  EXPECT_NEAR(r.report.generatrixLengthMin, slant, 1e-9);
  for (size_t q = 0; q < t.size(); ++q) {
    const TrajectoryPoint& p = t.points[q];
    EXPECT_NEAR(p.tangent.norm(), 1.0, 1e-12);
    EXPECT_NEAR(p.build.norm(), 1.0, 1e-12);
    EXPECT_NEAR(p.normal.dot(p.tangent), 0.0, 1e-12);
    EXPECT_NEAR((p.build - p.normal.cross(p.tangent)).norm(), 0.0, 1e-12);
    if (q + 1 < t.size()) {
      EXPECT_GT(p.tangent.dot(t.points[q + 1].position - p.position), 0.0);
    }
    // The generatrix of this point, rotated to its angle: b must point up it (close to it in the
    // modulated phase; ramps tilt it where their seams climb).
    const double a = test::angleOf(p.generatrix, n);
    const Vec3 gen(up.x() * std::cos(a), up.x() * std::sin(a), up.z());
    EXPECT_GT(p.build.dot(gen), 0.0);
    if (phaseOfRevolution(p.revolution, r.report) == SpiralPhase::Modulated) {
      EXPECT_GT(p.build.dot(gen), 0.99);
    }
    const Vec3 below = q >= static_cast<size_t>(n) ? t.points[q - n].position : g.lines[p.generatrix].front();
    if (q < static_cast<size_t>(n))
      EXPECT_NEAR(p.height, (p.position - below).z() / p.build.z(), 1e-9) << q;
    else
      EXPECT_NEAR(p.height, (p.position - below).dot(p.build), 1e-9) << q;
    // The point lies on the cone.
    const double z = p.position.z();
    EXPECT_NEAR(p.position.head<2>().norm(), 40.0 - 15.0 * z / 60.0, 1e-9);
  }
  EXPECT_NEAR(t.points.back().position.z(), 60.0, 1e-9);
  EXPECT_TRUE(r.report.feasible);
  EXPECT_NEAR(r.report.heightMean, 1.5, 0.015);
}
