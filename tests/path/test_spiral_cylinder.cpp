// The thesis's warm-up (000_dbb97c2716e10cc3.txt §3.2.2-3.2.4, Table 3.1): a thin cylinder R = 50, H = 100 mm
// with straight vertical generatrices, h = 1 mm ±10 %. Every expected number here comes from closed forms of
// the cylinder and of the ramp rule, not from the library.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "analytic_generatrices.h"
#include "spira/base/progress.h"
#include "spira/path/spiral_builder.h"

using namespace spira;

namespace {

constexpr double kR = 50.0, kH = 100.0;
constexpr int kN = 360;

// The ramp rule of docs/method.md M14 at ±10 % (4 full ramps), written out: the transition ramp ends at
// `top`, the constant revolution is laid at `c`.
struct Ramps {
  double top, c;
  double start(int r, double u) const
  {
    if (r < 4) return 0.9 + 0.2 * u;
    if (r == 4) return 0.9 + (top - 0.9) * u;
    return c;
  }
  double end(int r, double u) const
  {
    if (r == 0) return c;
    if (r == 1) return top - (top - 0.9) * u;
    return 1.1 - 0.2 * u;
  }
  double startSum(double u) const
  {
    double s = 0.0;
    for (int r = 0; r < 6; ++r) s += start(r, u);
    return s;
  }
  double endSum(double u) const
  {
    double s = 0.0;
    for (int r = 0; r < 6; ++r) s += end(r, u);
    return s;
  }
};

const Ramps kNominal{1.0, 1.0};  // Fig. 3.5: transition 0.9 -> 1.0 mm, then 1.0 mm

// Uniform helix: the ramps climb c (n-1)/n where c is the modulated step d itself, and every step
// around the spiral is d / n. On the cylinder all generatrices share d, so the ramps take
// 9 + d (3n-1)/n (test::helixRampLength) and d = (H - 9) / (n_layer + (3n-1)/n), n_layer being
// the count consistent with its own d (test::uniformHelixLayers).
struct Helix {
  int nLayers;
  double d;
  Ramps ramps;
};

Helix uniformHelix(LayerMode mode)
{
  const auto [nLayers, d] = test::uniformHelixLayers(kH, 1.0, kN, mode == LayerMode::Floor);
  return {nLayers, d, {0.9 + d * (kN - 1.0) / kN - 0.8, d}};
}

SpiralSettings cylinderSettings(LayerMode mode)
{
  SpiralSettings s;
  s.h = 1.0;
  s.hMin = 0.9;
  s.hMax = 1.1;
  s.layerMode = mode;
  return s;
}

double u(int i)
{
  return static_cast<double>(i) / (kN - 1);
}

// Expected height z of revolution k on generatrix i, with Termination::Ramps.
std::vector<double> expectedZ(const Ramps& ramps, int nLayers)
{
  const int revs = 6 + nLayers + 6;
  std::vector<double> z(static_cast<size_t>(revs) * kN);
  for (int i = 0; i < kN; ++i) {
    double acc = 0.0;
    int k = 0;
    for (int r = 0; r < 6; ++r, ++k) z[k * kN + i] = acc += ramps.start(r, u(i));
    const double d = (kH - ramps.startSum(u(i)) - ramps.endSum(u(i))) / nLayers;
    for (int m = 0; m < nLayers; ++m, ++k) z[k * kN + i] = acc += d;
    for (int r = 0; r < 6; ++r, ++k) z[k * kN + i] = acc += ramps.end(r, u(i));
  }
  return z;
}

// True height on the cylinder: the tangent-plane part of the chord to the next point is
// R sin(dphi) around and dz up, b = n x t, theta is the angle between z and b.
double analyticHeight(double step, double dz)
{
  const double around = kR * std::sin(2.0 * kPi / kN);
  return step * around / std::hypot(around, dz);
}

// The first ring's: its distance along b from the substrate plane, z / cos(theta).
double analyticPlaneHeight(double z, double dz)
{
  const double around = kR * std::sin(2.0 * kPi / kN);
  return z * std::hypot(around, dz) / around;
}

void expectOnePolyline(const Trajectory& t, const std::vector<double>& z)
{
  const double chord = 2.0 * kR * std::sin(kPi / kN);
  for (size_t q = 1; q < t.size(); ++q) {
    const Vec3 jump = t.points[q].position - t.points[q - 1].position;
    const double localStep = z[q] - (q >= static_cast<size_t>(kN) ? z[q - kN] : 0.0);
    EXPECT_LE(jump.head<2>().norm(), chord + 1e-9) << q;
    EXPECT_LE(std::abs(jump.z()), localStep + 1e-9) << q;
  }
}

}  // namespace

TEST(SpiralCylinder, StartUpRevolutionsFollowTable31)
{
  NullProgress progress;
  const SpiralResult r =
      buildSpiral(test::cylinder(kR, kH, kN, 101), cylinderSettings(LayerMode::Floor), progress);
  const Helix helix = uniformHelix(LayerMode::Floor);
  EXPECT_EQ(r.report.nStartupRevolutions, 6);
  EXPECT_EQ(r.report.nEndRevolutions, 6);
  double z0 = 0.0, z1 = 0.0;
  for (int k = 0; k < 6; ++k) {
    z0 += helix.ramps.start(k, 0.0);
    z1 += helix.ramps.start(k, 1.0);
    const TrajectoryPoint& first = r.trajectory.points[k * kN];
    const TrajectoryPoint& last = r.trajectory.points[k * kN + kN - 1];
    EXPECT_NEAR(first.position.z(), z0, 1e-9) << k;
    EXPECT_NEAR(last.position.z(), z1, 1e-9) << k;
    EXPECT_EQ(first.revolution, k);
    EXPECT_EQ(last.generatrix, kN - 1);
    // Deposits of the first four revolutions: 0.9 at the start, 1.1 at the end (Table 3.1).
    const double below = k ? r.trajectory.points[(k - 1) * kN + kN - 1].position.z() : 0.0;
    if (k < 4) {
      EXPECT_NEAR(first.position.z(), 0.9 * (k + 1), 1e-9);  // j h_min
      EXPECT_NEAR(last.position.z(), 1.1 * (k + 1), 1e-9);   // j h_max
      EXPECT_NEAR(last.position.z() - below, 1.1, 1e-9);
    }
  }
  // The ramps span the window (Table 3.1: 0.9 at a revolution's start, 1.1 at its end) and the
  // report says so, apart from the modulated rows' own range.
  double lo = 1e9, hi = -1e9;
  for (const TrajectoryPoint& p : r.trajectory.points)
    if (p.revolution < 6 || p.revolution >= r.report.nRevolutions - 6) {
      lo = std::min(lo, p.height);
      hi = std::max(hi, p.height);
    }
  EXPECT_DOUBLE_EQ(r.report.rampHeightMin, lo);
  EXPECT_DOUBLE_EQ(r.report.rampHeightMax, hi);
  EXPECT_NEAR(lo, 0.9, 0.005);
  EXPECT_NEAR(hi, 1.1, 0.005);
  EXPECT_LT(r.report.rampHeightMin, r.report.heightMin);
  EXPECT_GT(r.report.rampHeightMax, r.report.heightMax);
}

TEST(SpiralCylinder, ModulatedDepositIsUniformAndReachesTheTop)
{
  NullProgress progress;
  const SpiralResult r =
      buildSpiral(test::cylinder(kR, kH, kN, 101), cylinderSettings(LayerMode::Floor), progress);
  const Helix helix = uniformHelix(LayerMode::Floor);
  const int nLayers = helix.nLayers;
  ASSERT_EQ(r.report.nLayers, nLayers);
  ASSERT_EQ(r.report.nRevolutions, 6 + nLayers + 6);
  ASSERT_EQ(r.trajectory.size(), static_cast<size_t>(r.report.nRevolutions) * kN);
  EXPECT_NEAR(r.report.seamStep, helix.d / kN, 1e-9);
  const std::vector<double> z = expectedZ(helix.ramps, nLayers);
  for (size_t q = 0; q < r.trajectory.size(); ++q) {
    const TrajectoryPoint& p = r.trajectory.points[q];
    const double a = test::angleOf(p.generatrix, kN);
    ASSERT_NEAR(p.position.z(), z[q], 1e-9) << q;
    ASSERT_NEAR(p.position.x(), kR * std::cos(a), 1e-9);
    ASSERT_NEAR(p.position.y(), kR * std::sin(a), 1e-9);
  }
  // After the start-up every deposit is the same, and inside the window; the spiral climbs d / n
  // per point, seam included.
  const double first = r.trajectory.points[6 * kN].height;
  for (int k = 6; k < 6 + nLayers; ++k)
    for (int i = 0; i < kN; ++i) {
      const size_t q = static_cast<size_t>(k) * kN + i;
      EXPECT_NEAR(z[q] - z[q - kN], helix.d, 1e-9);
      EXPECT_NEAR(z[q] - z[q - 1], helix.d / kN, 1e-9);
      EXPECT_NEAR(r.trajectory.points[q].height, first, 1e-6);
    }
  EXPECT_GT(first, 0.9);
  EXPECT_LT(first, 1.1);
  EXPECT_NEAR(first, analyticHeight(helix.d, helix.d / kN), 1e-9);
  // The last revolution lies on the upper edge.
  for (int i = 0; i < kN; ++i)
    EXPECT_NEAR(r.trajectory.points[r.trajectory.size() - kN + i].position.z(), kH, 1e-9);
  expectOnePolyline(r.trajectory, z);
  EXPECT_TRUE(r.report.feasible);
  EXPECT_EQ(r.report.modulatedViolations, 0u);
  EXPECT_NEAR(r.report.heightMin, first, 1e-6);
  EXPECT_NEAR(r.report.heightMax, first, 1e-6);
  EXPECT_NEAR(r.report.pathLength, r.trajectory.length(), 1e-9);
}

TEST(SpiralCylinder, CenteredModeCentresTheDepositOnH)
{
  NullProgress progress;
  const SpiralResult r =
      buildSpiral(test::cylinder(kR, kH, kN, 101), cylinderSettings(LayerMode::Centered), progress);
  const Helix helix = uniformHelix(LayerMode::Centered);
  ASSERT_EQ(r.report.nLayers, helix.nLayers);
  for (size_t q = 6 * kN; q < static_cast<size_t>(6 + r.report.nLayers) * kN; ++q) {
    EXPECT_NEAR(r.trajectory.points[q].height, 1.0, 0.01) << q;
    EXPECT_GT(r.trajectory.points[q].height, 0.9);
    EXPECT_LT(r.trajectory.points[q].height, 1.1);
  }
  EXPECT_NEAR(r.report.heightMean, 1.0, 0.01);
  EXPECT_TRUE(r.report.feasible);
  expectOnePolyline(r.trajectory, expectedZ(helix.ramps, r.report.nLayers));
}

// Every height against the closed form, ramps included.
TEST(SpiralCylinder, HeightChannelMatchesTheAnalyticTrueHeight)
{
  NullProgress progress;
  const SpiralResult r =
      buildSpiral(test::cylinder(kR, kH, kN, 101), cylinderSettings(LayerMode::Floor), progress);
  const std::vector<double> z = expectedZ(uniformHelix(LayerMode::Floor).ramps, r.report.nLayers);
  const size_t count = r.trajectory.size();
  for (size_t q = 0; q < count; ++q) {
    const double step = z[q] - (q >= static_cast<size_t>(kN) ? z[q - kN] : 0.0);
    // The last point of a revolution (the seam) and the last point of the path take the chord
    // arriving at them; every other point the chord to the next point.
    const bool seam = q % kN == static_cast<size_t>(kN - 1);
    const size_t from = q + 1 < count && !seam ? q : q - 1;
    const double rise = z[from + 1] - z[from];
    EXPECT_NEAR(r.trajectory.points[q].height,
                q < static_cast<size_t>(kN) ? analyticPlaneHeight(z[q], rise) : analyticHeight(step, rise),
                1e-9)
        << q;
  }
}

// The start-up as the figures draw it (transition 0.9 -> 1.0 mm, then 1.0 mm): the spiral climbs
// 0.9 mm per revolution whatever the layer step d, so each seam rises d - 0.9 in one segment:
// 0.008 mm in floor mode (d = 88.1 / 97), 0.101 mm in centred mode (d = 88.1 / 88). On this
// cylinder (0.87 mm between generatrices) both stay inside the window.
TEST(SpiralCylinder, NominalTransitionLeavesTheSeamStepToTheLayerStep)
{
  NullProgress progress;
  for (LayerMode mode : {LayerMode::Floor, LayerMode::Centered}) {
    SpiralSettings s = cylinderSettings(mode);
    s.startupTransition = StartupTransition::ToNominal;
    const SpiralResult r = buildSpiral(test::cylinder(kR, kH, kN, 101), s, progress);
    const double modulated = kH - kNominal.startSum(0.0) - kNominal.endSum(0.0);  // 88.1
    const int nLayers = mode == LayerMode::Floor ? 97 : 88;
    ASSERT_EQ(r.report.nLayers, nLayers);
    const std::vector<double> z = expectedZ(kNominal, nLayers);
    for (size_t q = 0; q < r.trajectory.size(); ++q)
      ASSERT_NEAR(r.trajectory.points[q].position.z(), z[q], 1e-9);
    const double d = modulated / nLayers;
    EXPECT_NEAR(r.report.seamStep, d - 0.9, 1e-9);
    // A seam point of the modulated phase and a point inside a revolution: both lean with the
    // revolution's climb, 0.9 mm over kN - 1 segments; the seam's own rise is reported apart.
    EXPECT_NEAR(r.trajectory.points[8 * kN - 1].height, analyticHeight(d, 0.9 / (kN - 1)), 1e-9);
    EXPECT_NEAR(r.trajectory.points[8 * kN - 2].height, analyticHeight(d, 0.9 / (kN - 1)), 1e-9);
    EXPECT_NEAR(z[8 * kN] - z[8 * kN - 1], d - 0.9, 1e-9);
    EXPECT_TRUE(r.report.feasible);
  }
}

// The thesis as written: figures' start-up, no termination, d_i = l_i / n_layer absorbs the
// start-up climb. The top is still reached, but the seam rise grows to about d, in one segment.
TEST(SpiralCylinder, AbsorbTerminationReachesTheTopWithAGrowingSeamStep)
{
  NullProgress progress;
  SpiralSettings s = cylinderSettings(LayerMode::Floor);
  s.startupTransition = StartupTransition::ToNominal;
  s.termination = Termination::Absorb;
  const SpiralResult r = buildSpiral(test::cylinder(kR, kH, kN, 101), s, progress);
  const int nLayers = static_cast<int>(std::floor((kH - kNominal.startSum(1.0)) / 0.9 + 1e-9));
  ASSERT_EQ(r.report.nLayers, nLayers);
  ASSERT_EQ(r.report.nEndRevolutions, 0);
  ASSERT_EQ(r.trajectory.size(), static_cast<size_t>(6 + nLayers) * kN);
  std::vector<double> z(r.trajectory.size());
  for (int i = 0; i < kN; ++i) {
    double acc = 0.0;
    for (int k = 0; k < 6; ++k) z[k * kN + i] = acc += kNominal.start(k, u(i));
    const double d = (kH - acc) / nLayers;
    for (int m = 1; m <= nLayers; ++m) z[(5 + m) * kN + i] = acc + m * d;
  }
  for (size_t q = 0; q < r.trajectory.size(); ++q)
    ASSERT_NEAR(r.trajectory.points[q].position.z(), z[q], 1e-9) << q;
  // The seam rise grows from about 0 to about d over the build, one segment each time; the seam
  // points' deposits are their steps (in the window), the rise is reported apart.
  EXPECT_NEAR(z[6 * kN] - z[6 * kN - 1], 0.0, 0.01);
  EXPECT_NEAR(z[z.size() - kN] - z[z.size() - kN - 1], 0.9, 0.01);
  EXPECT_NEAR(r.report.seamRiseMax, z[z.size() - kN] - z[z.size() - kN - 1], 1e-3);
  EXPECT_NEAR(r.trajectory.points.back().position.z(), kH, 1e-9);
  EXPECT_TRUE(r.report.violations.empty());
  EXPECT_TRUE(r.report.feasible);
  expectOnePolyline(r.trajectory, z);
}
