// Closed parts: every generatrix ends at the closure point, where the spiral must end once.
#include <gtest/gtest.h>

#include <cmath>

#include "analytic_generatrices.h"
#include "spira/base/progress.h"
#include "spira/path/spiral_builder.h"

using namespace spira;

namespace {

constexpr double kR = 50.0;
constexpr int kN = 360, kPoints = 200;

SpiralSettings domeSettings()
{
  SpiralSettings s;
  s.h = 1.0;
  s.hMin = 0.9;
  s.hMax = 1.1;
  s.layerMode = LayerMode::Floor;  // the thesis's count, which uniformHelixLayers computes
  s.minRevolutionLength = 0.0;     // h: only the last revolution (the pole itself) folds
  return s;
}

}  // namespace

TEST(SpiralClosed, HemisphereConvergesToThePoleOnce)
{
  NullProgress progress;
  const Generatrices g = test::hemisphereMeridians(kR, kN, kPoints);
  const SpiralResult r = buildSpiral(g, domeSettings(), progress);
  const Trajectory& t = r.trajectory;
  const Vec3 pole(0, 0, kR);

  // Meridian polyline length, and the layer count from it.
  const double length = (kPoints - 1) * 2.0 * kR * std::sin(0.25 * kPi / (kPoints - 1));
  const int nLayers = test::uniformHelixLayers(length, 1.0, kN, true).first;
  EXPECT_NEAR(r.report.generatrixLengthMin, length, 1e-9);
  ASSERT_EQ(r.report.nLayers, nLayers);
  ASSERT_EQ(r.report.nRevolutions, 6 + nLayers + 6);

  // The last revolution (the pole n times) became one point; the one before is a ~6 mm circle.
  EXPECT_EQ(r.report.collapsedRevolutions, 1);
  ASSERT_EQ(t.size(), static_cast<size_t>(r.report.nRevolutions - 1) * kN + 1);
  EXPECT_EQ(t.points.back().position, pole);
  EXPECT_EQ(t.points.back().revolution, r.report.nRevolutions - 1);
  size_t atPole = 0;
  for (const auto& p : t.points) atPole += (p.position - pole).norm() < 1e-6;
  EXPECT_EQ(atPole, 1u);
  // The final jump is one step of the last termination ramp: h_min at the last generatrix,
  // stretched by 1 / cos(theta) where the layers lean on the meridians near the pole.
  const double lastJump = (t.points.back().position - t.points[t.size() - 2].position).norm();
  EXPECT_LT(lastJump, 0.9 * 1.001);
  EXPECT_GT(lastJump, 0.85);
  // The gap to the pole is measured along generatrix 0, where the last ramp lays h_max.
  EXPECT_NEAR(r.report.closureGap, 1.1, 1.1 * 0.001);
  // Every point, ramps and closure point included, lies in the window.
  EXPECT_TRUE(r.report.violations.empty());

  // On the sphere (chordal error of a 199-segment meridian: 4e-4 mm), climbing every generatrix.
  for (size_t q = 0; q < t.size(); ++q) {
    const TrajectoryPoint& p = t.points[q];
    EXPECT_NEAR(p.position.norm(), kR, 5e-4);
    if (q >= static_cast<size_t>(kN) && q + 1 < t.size()) {
      const TrajectoryPoint& below = t.points[q - kN];
      EXPECT_GT(p.position.z(), below.position.z());
      EXPECT_LT(p.position.head<2>().norm(), below.position.head<2>().norm());
    }
  }
  // No jump longer than the local step: one generatrix spacing around plus one step up.
  for (size_t q = 1; q < t.size(); ++q) {
    const Vec3& a = t.points[q - 1].position;
    const Vec3& b = t.points[q].position;
    const double around = 2.0 * a.head<2>().norm() * std::sin(kPi / kN);
    EXPECT_LE((b - a).norm(), std::hypot(around, 1.1) + 1e-6) << q;
  }
  EXPECT_TRUE(r.report.feasible);
  EXPECT_EQ(r.report.modulatedViolations, 0u);
  EXPECT_GT(r.report.heightMin, 0.9);
  EXPECT_LT(r.report.heightMax, 1.1);
}

// Heights recomputed from positions and b: d is the chord along the meridian, 2 R sin((lat -
// lat_below) / 2); the first ring's is its distance along b from the equator's plane it rests on.
TEST(SpiralClosed, HeightsRecomputedFromPositionsAgree)
{
  NullProgress progress;
  const Generatrices g = test::hemisphereMeridians(kR, kN, kPoints);
  const SpiralResult r = buildSpiral(g, domeSettings(), progress);
  const Trajectory& t = r.trajectory;
  const auto lat = [](const Vec3& p) { return std::asin(std::min(1.0, p.z() / p.norm())); };
  // The closure point takes the height of the last ring (its gap is covered by that bead's width).
  EXPECT_EQ(t.points.back().height, t.points[t.size() - 2].height);
  for (size_t q = 0; q + 1 < t.size(); ++q) {
    const TrajectoryPoint& p = t.points[q];
    const size_t prev = q - kN;
    const Vec3 below = q < static_cast<size_t>(kN) ? g.lines[p.generatrix].front() : t.points[prev].position;
    const Vec3 v = p.position - below;
    const double d = 2.0 * kR * std::sin(0.5 * (lat(p.position) - lat(below)));
    if (q < static_cast<size_t>(kN))
      EXPECT_NEAR(p.height, p.position.z() / p.build.z(), 1e-12) << q;
    else
      EXPECT_NEAR(p.height, d * v.dot(p.build) / v.norm(), 2e-5 * d) << q;
    // b points up the meridian, toward the pole.
    const Vec3 towardPole = (Vec3(0, 0, kR) - p.position).normalized();
    EXPECT_GT(p.build.dot(towardPole), 0.0) << q;
  }
}

// A larger minimum revolution length folds more of the tiny last revolutions into the pole.
TEST(SpiralClosed, MinimumRevolutionLengthFoldsTinyRevolutions)
{
  NullProgress progress;
  const Generatrices g = test::hemisphereMeridians(kR, kN, kPoints);
  SpiralSettings s = domeSettings();
  s.minRevolutionLength = 20.0;
  const SpiralResult r = buildSpiral(g, s, progress);
  const Trajectory& t = r.trajectory;
  EXPECT_GT(r.report.collapsedRevolutions, 1);
  ASSERT_EQ(t.size(), static_cast<size_t>(r.report.nRevolutions - r.report.collapsedRevolutions) * kN + 1);
  EXPECT_EQ(t.points.back().position, Vec3(0, 0, kR));
  // The last kept revolution is at least 20 mm around (radius >= 20 / 2 pi, to the chord error).
  const Vec3& lastKept = t.points[t.size() - 2].position;
  EXPECT_GT(lastKept.head<2>().norm() * 2.0 * kPi, 20.0 * 0.99);
  // ...and the first folded one was shorter: its radius is below 20 / 2 pi.
  double perimeter = 0.0;
  const SpiralResult full = buildSpiral(g, domeSettings(), progress);
  const size_t firstFolded = static_cast<size_t>(r.report.nRevolutions - r.report.collapsedRevolutions) * kN;
  for (int i = 1; i < kN; ++i)
    perimeter += (full.trajectory.points[firstFolded + i].position -
                  full.trajectory.points[firstFolded + i - 1].position)
                     .norm();
  EXPECT_LT(perimeter, 20.0);
}

// With the figures' start-up the seam rises d - 0.9 h in one segment whatever the radius: 0.1 mm
// in centred mode (d about h), which near the pole, where neighbouring generatrices are a fraction
// of a millimetre apart, is a steep step for the torch. The default uniform helix spreads the rise
// over the revolution: its seam rises d / n like every other point. Both keep every deposit in the
// window (the seam frames follow the revolution, spiral_frames.h).
TEST(SpiralClosed, UniformHelixSpreadsTheSeamRiseThatTheNominalTransitionConcentrates)
{
  NullProgress progress;
  const Generatrices g = test::hemisphereMeridians(kR, kN, kPoints);
  SpiralSettings s = domeSettings();
  s.layerMode = LayerMode::Centered;
  const SpiralResult helix = buildSpiral(g, s, progress);
  EXPECT_TRUE(helix.report.feasible);
  // Stretched termination ramps (1 / cos(theta) up to ~1.0004 near the pole) move the seam by
  // ~2e-5 mm from the ideal d / n.
  EXPECT_NEAR(helix.report.seamStep, helix.report.stepMin / kN, 1e-4);

  s.startupTransition = StartupTransition::ToNominal;
  const SpiralResult nominal = buildSpiral(g, s, progress);
  EXPECT_TRUE(nominal.report.feasible);
  EXPECT_NEAR(nominal.report.seamStep, nominal.report.stepMin - 0.9, 1e-3);
  EXPECT_GT(nominal.report.seamStep, 20.0 * helix.report.seamStep);
}
