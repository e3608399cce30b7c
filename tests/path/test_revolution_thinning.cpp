#include <gtest/gtest.h>

#include <cmath>

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/path/revolution_thinning.h"
#include "spira/verify/deposit_check.h"

namespace spira {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kPerRevolution = 36;
constexpr double kRadius = 20.0, kStep = 2.0, kSpeed = 5.0, kFeed = 2300.0 / 60.0;

// A uniform helix around the z axis: 2 mm a revolution, each point at the top of its layer.
Trajectory helix(int revolutions)
{
  Trajectory t;
  for (int r = 0; r < revolutions; ++r)
    for (int g = 0; g < kPerRevolution; ++g) {
      const double a = 2.0 * kPi * g / kPerRevolution;
      TrajectoryPoint p;
      p.position =
          Vec3(kRadius * std::cos(a), kRadius * std::sin(a), kStep * (r + 1 + double(g) / kPerRevolution));
      p.normal = Vec3(std::cos(a), std::sin(a), 0.0);
      p.tangent = Vec3(-std::sin(a), std::cos(a), 0.0);
      p.build = p.normal.cross(p.tangent);
      p.revolution = r;
      p.generatrix = g;
      p.height = kStep;
      p.travelSpeed = kSpeed;
      p.wireFeed = kFeed;
      t.points.push_back(p);
    }
  return t;
}

TEST(RevolutionThinning, HalvesTheBandWithTwiceTheRevolutionsAtTwiceTheSpeed)
{
  const Trajectory planned = helix(10);
  const ThinningResult out = thinRevolutions(planned, {0, 3, 7, 0.5});
  EXPECT_EQ(out.revolutionsAdded, 4);
  EXPECT_DOUBLE_EQ(out.ratio, 0.5);
  EXPECT_EQ(out.first, 3);
  EXPECT_EQ(out.last, 11);
  const Trajectory& t = out.trajectory;
  ASSERT_EQ(t.size(), planned.size() + 4 * kPerRevolution);
  // Up to the band's base, as planned.
  for (size_t i = 0; i < 4 * kPerRevolution; ++i) EXPECT_EQ(t.points[i], planned.points[i]);
  // Each new revolution climbs 1 mm on every generatrix: half way between the planned layers.
  for (int j = 1; j <= 8; ++j)
    for (int g = 0; g < kPerRevolution; ++g) {
      const TrajectoryPoint& p = t.points[size_t((3 + j) * kPerRevolution + g)];
      const TrajectoryPoint& base = planned.points[size_t(3 * kPerRevolution + g)];
      EXPECT_NEAR(p.position.z(), base.position.z() + 0.5 * kStep * j, 1e-9);
      EXPECT_NEAR(std::hypot(p.position.x(), p.position.y()), kRadius, 1e-9);
      EXPECT_EQ(p.revolution, 3 + j);
      EXPECT_EQ(p.generatrix, g);
      EXPECT_NEAR(p.height, 1.0, 1e-12);
      EXPECT_NEAR(p.travelSpeed, 2.0 * kSpeed, 1e-12);  // same wire feed, half the cross-section
      EXPECT_EQ(p.wireFeed, kFeed);
      EXPECT_NEAR(p.build.dot(p.tangent), 0.0, 1e-12);
      EXPECT_NEAR(p.build.norm(), 1.0, 1e-12);
    }
  // The band ends on the planned revolution 7 (j = 8 above); after it the path is unchanged but
  // renumbered.
  for (size_t i = 8 * kPerRevolution; i < planned.size(); ++i) {
    TrajectoryPoint expected = planned.points[i];
    expected.revolution += 4;
    const TrajectoryPoint& p = t.points[i + 4 * kPerRevolution];
    EXPECT_NEAR((p.position - expected.position).norm(), 0.0, 1e-12);
    expected.position = p.position;
    EXPECT_EQ(p, expected);
  }
}

// A ratio that does not divide the band: a whole number of revolutions, the deposit conserved on
// every generatrix, and the wire feed scaled instead where the path was not fed at one speed.
TEST(RevolutionThinning, KeepsTheBandsDepositAndScalesTheFeedOfAModulatedWireFeed)
{
  Trajectory planned = helix(8);
  for (TrajectoryPoint& p : planned.points) p.wireFeed = kFeed * (1.0 + 0.01 * p.generatrix);
  planned.extra["torch_tilt"].assign(planned.size(), 3.0);
  const ThinningResult out = thinRevolutions(planned, {0, 1, 6, 0.7});
  EXPECT_EQ(out.revolutionsAdded, 3);  // ceil(5 / 0.7) = 8 revolutions for 5
  EXPECT_DOUBLE_EQ(out.ratio, 5.0 / 8.0);
  for (int g = 0; g < kPerRevolution; ++g) {
    double laid = 0.0;
    for (int j = 1; j <= 8; ++j) {
      const TrajectoryPoint& p = out.trajectory.points[size_t((1 + j) * kPerRevolution + g)];
      laid += p.height;
      EXPECT_NEAR(p.height, kStep * 5.0 / 8.0, 1e-12);
      EXPECT_NEAR(p.travelSpeed, kSpeed, 1e-12);
      EXPECT_NEAR(p.wireFeed, kFeed * (1.0 + 0.01 * g) * 5.0 / 8.0, 1e-9);
    }
    EXPECT_NEAR(laid, 5.0 * kStep, 1e-9);
  }
  ASSERT_EQ(out.trajectory.extra.at("torch_tilt").size(), out.trajectory.size());
  EXPECT_EQ(out.trajectory.extra.at("torch_tilt")[5 * kPerRevolution], 3.0);
}

// The thinned path, judged on its own by the deposit check: every bead of the band and above it
// supported at its thinner height inside a window that allows it, and every bead of the band refused
// by the planned window. (The helix's first revolution, without start-up ramps, is not judged.)
TEST(RevolutionThinning, ThinnedPathPassesTheDepositCheckOfItsWindow)
{
  const Trajectory planned = helix(10);
  const ThinningResult out = thinRevolutions(planned, {0, 3, 7, 0.5});
  const size_t bandBegin = 4 * kPerRevolution, bandEnd = 12 * kPerRevolution;
  DepositCheckSettings s;
  s.substrateZ = 0.0;
  s.beadWidth = 4.0;
  s.hMin = 0.9;
  s.hMax = 2.2;
  NullProgress progress;
  const auto flagsFrom = [&](const DepositCheckReport& r, DepositDefect kind) {
    size_t inBand = 0, above = 0;
    for (const DepositFlag& f : r.flags) {
      if (f.point >= bandBegin && f.point < bandEnd) inBand += f.kind == kind;
      if (f.point >= bandEnd) ++above;
    }
    return std::pair{inBand, above};
  };
  const DepositCheckReport wide = checkDeposits(out.trajectory, nullptr, s, progress);
  for (const DepositFlag& f : wide.flags) EXPECT_LT(f.point, size_t(kPerRevolution)) << wide.summary();
  s.hMin = 1.8;
  const DepositCheckReport plannedWindow = checkDeposits(out.trajectory, nullptr, s, progress);
  EXPECT_EQ(flagsFrom(plannedWindow, DepositDefect::Thin), std::pair(size_t(8 * kPerRevolution), size_t(0)));
}

TEST(RevolutionThinning, RefusesABandItCannotThin)
{
  Trajectory planned = helix(6);
  EXPECT_THROW(thinRevolutions(planned, {0, 3, 3, 0.5}), InputError);  // no step
  EXPECT_THROW(thinRevolutions(planned, {0, 2, 9, 0.5}), InputError);  // past the end
  EXPECT_THROW(thinRevolutions(planned, {1, 1, 3, 0.5}), InputError);  // no such path
  EXPECT_THROW(thinRevolutions(planned, {0, 1, 3, 1.5}), InputError);  // not thinner
  planned.points.pop_back();                                           // the last revolution one point short
  EXPECT_THROW(thinRevolutions(planned, {0, 1, 5, 0.5}), InputError);
}

}  // namespace
}  // namespace spira
