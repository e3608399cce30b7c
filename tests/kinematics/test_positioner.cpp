#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "robot_files.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"
#include "spira/kinematics/tilt_rotate_positioner.h"

namespace spira {
namespace {

using test::robotUrdf;
using Axes = TiltRotatePositioner::Axes;

TiltRotatePositioner positioner()
{
  return TiltRotatePositioner(
      KinematicChain::fromUrdfFile(robotUrdf("positioner_2axis"), "base_link", "table_top"));
}

Vec3 randomDirection(std::mt19937& rng)
{
  std::normal_distribution<double> n(0.0, 1.0);
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

TEST(TiltRotatePositioner, ForwardKinematicsOfTheBundledPositioner)
{
  const TiltRotatePositioner p = positioner();
  // Table top 800 mm above the floor at E1 = 0; 150 mm from the tilt axis (650 mm up).
  EXPECT_NEAR((p.forward(Axes::Zero()).translation() - Vec3(0, 0, 800)).norm(), 0.0, 1e-9);
  const Transform t = p.forward(Axes(degToRad(90), degToRad(30)));
  EXPECT_NEAR((t.translation() - Vec3(150, 0, 650)).norm(), 0.0, 1e-9);  // tilted about +Y: z -> x
  const Mat3 expected =
      (Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()) * Eigen::AngleAxisd(kPi / 6, Vec3::UnitZ()))
          .toRotationMatrix();
  EXPECT_NEAR((t.linear() - expected).norm(), 0.0, 1e-12);
}

TEST(TiltRotatePositioner, TurnsAnyDirectionVertical)
{
  const TiltRotatePositioner p = positioner();
  std::mt19937 rng(21);
  double worst = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 b = randomDirection(rng);
    const std::vector<Axes> all = p.solveAll(b);
    ASSERT_EQ(all.size(), 2u);
    for (const Axes& e : all) worst = std::max(worst, (p.forward(e).linear() * b - Vec3::UnitZ()).norm());
    // 004_bd0df31205c0c3c0.txt Eq. C.24-C.25 (its R_X, R_Y, R_Z are b's components): q7 = atan2(sqrt(bx^2 +
    // by^2), bz), q8 = atan2(by, -bx), and Ry(q7) Rz(q8) b = z; it is the first (e1 >= 0) branch here.
    const double q7 = std::atan2(std::hypot(b.x(), b.y()), b.z()), q8 = std::atan2(b.y(), -b.x());
    const Vec3 thesis = Eigen::AngleAxisd(q7, Vec3::UnitY()) * (Eigen::AngleAxisd(q8, Vec3::UnitZ()) * b);
    ASSERT_LT((thesis - Vec3::UnitZ()).norm(), 1e-12);
    EXPECT_NEAR(wrapToPi(all[0][0] - q7), 0.0, 1e-9);
    EXPECT_NEAR(wrapToPi(all[0][1] - q8), 0.0, 1e-9);
    // The other branch tilts the other way and turns half a revolution more.
    EXPECT_NEAR(wrapToPi(all[1][0] + q7), 0.0, 1e-9);
    EXPECT_NEAR(wrapToPi(all[1][1] - q8 - kPi), 0.0, 1e-9);
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(TiltRotatePositioner, FollowsThePreviousBranchAndUnwindsTheRotation)
{
  const TiltRotatePositioner p = positioner();
  // A build direction tilted 30 deg from the table normal, swinging round 2.5 turns: the table
  // rotation keeps counting past +-180 deg (E2 has +-360) and the tilt stays on its side.
  Axes previous(degToRad(-10), 0.0);
  double last2 = 0.0;
  for (int k = 0; k <= 900; ++k) {
    const double a = degToRad(k);
    const Vec3 b(std::sin(degToRad(30)) * std::cos(a), std::sin(degToRad(30)) * std::sin(a),
                 std::cos(degToRad(30)));
    const std::optional<Axes> e = p.solve(b, previous);
    ASSERT_TRUE(e);
    EXPECT_LT((p.forward(*e).linear() * b - Vec3::UnitZ()).norm(), 1e-9);
    EXPECT_NEAR((*e)[0], degToRad(-30), 1e-9) << k;  // stays on the e1 < 0 side chosen by the seed
    if (k > 0) {
      EXPECT_LT(std::abs((*e)[1] - last2), degToRad(1.0) + 1e-9);
    }
    last2 = (*e)[1];
    previous = *e;
  }
  EXPECT_NEAR(last2, -degToRad(900), 1e-6);  // 2.5 turns from the start, no wrap
  EXPECT_LT(p.limitMargin(previous), 0.0);   // beyond +-360 deg: flagged by the caller
}

TEST(TiltRotatePositioner, DirectionAlongTheTableNormalKeepsTheRotation)
{
  const TiltRotatePositioner p = positioner();
  const std::optional<Axes> e = p.solve(Vec3::UnitZ(), Axes(0.2, 1.3));
  ASSERT_TRUE(e);
  EXPECT_NEAR((*e)[0], 0.0, 1e-12);
  EXPECT_NEAR((*e)[1], 1.3, 1e-12);
}

// The angle (rad) between the build direction b turned by the positioner at e and the vertical.
double leanAfter(const TiltRotatePositioner& p, const Vec3& b, const Axes& e)
{
  return std::acos(std::clamp((p.forward(e).linear() * b).normalized().z(), -1.0, 1.0));
}

TEST(TiltRotatePositioner, WithinAToleranceTheRotationKeepsToItsTarget)
{
  const TiltRotatePositioner p = positioner();
  const double tolerance = degToRad(2.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 500; ++k) {
    // A build direction 0 .. 10 deg off the table normal, a target rotation anywhere.
    const double lean = degToRad(10.0 * unit(rng)), azimuth = 2.0 * kPi * unit(rng);
    const Vec3 b(std::sin(lean) * std::cos(azimuth), std::sin(lean) * std::sin(azimuth), std::cos(lean));
    const double target = 20.0 * kPi * (unit(rng) - 0.5);
    const std::optional<Axes> e = p.solveWithin(b, tolerance, target, 0.0);
    ASSERT_TRUE(e);
    ASSERT_LE(leanAfter(p, b, *e), tolerance + 1e-9) << k;
    if (lean <= tolerance) {
      EXPECT_EQ((*e)[1], target);  // free: the rotation is left where it was aimed
      continue;
    }
    // No rotation nearer the target keeps the direction within the tolerance: scan 0.05 deg steps
    // between the target and the answer.
    const double found = (*e)[1] - target;
    EXPECT_LE(std::abs(found), kPi / 2.0 + 1e-9);  // one of the two exact branches is that near
    // With a tolerance of 90 deg every rotation is allowed, and the tilt is the best for it.
    const auto bestLean = [&](double rotation) {
      const std::optional<Axes> kept = p.solveWithin(b, kPi / 2.0, rotation, 0.0);
      EXPECT_TRUE(kept && (*kept)[1] == rotation);
      return kept ? leanAfter(p, b, *kept) : 0.0;
    };
    const double step = std::copysign(degToRad(0.05), found);
    for (double f = 0.0; std::abs(f) < std::abs(found) - degToRad(0.1); f += step)
      ASSERT_GT(bestLean(target + f), tolerance) << k << " at " << f;
  }
}

TEST(TiltRotatePositioner, TheTiltIsTheBestForTheRotationItKeeps)
{
  const TiltRotatePositioner p = positioner();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 50; ++k) {
    const Vec3 b = randomDirection(rng);
    const double rotation = 2.0 * kPi * unit(rng);
    // With a tolerance of 90 deg no direction needs turning: the rotation is kept.
    const std::optional<Axes> e = p.solveWithin(b, kPi / 2.0, rotation, 0.0);
    ASSERT_TRUE(e);
    EXPECT_EQ((*e)[1], rotation);
    double best = kPi;
    for (int t = -18000; t <= 18000; ++t)
      best = std::min(best, leanAfter(p, b, Axes(degToRad(0.01 * t), rotation)));
    EXPECT_LE(leanAfter(p, b, *e), best + 1e-9) << k;
  }
}

TEST(TiltRotatePositioner, WithoutToleranceItIsTheExactBranchNearestTheTarget)
{
  const TiltRotatePositioner p = positioner();
  std::mt19937 rng(11);
  for (int k = 0; k < 500; ++k) {
    const Vec3 b = randomDirection(rng);
    const double target = 4.0;
    const std::optional<Axes> e = p.solveWithin(b, 0.0, target, 0.3);
    ASSERT_TRUE(e);
    EXPECT_LT(leanAfter(p, b, *e), 1e-6);
    double nearest = 1e9;  // the exact branches' rotations, on the turn nearest the target
    for (const Axes& exact : p.solveAll(b))
      nearest = std::min(nearest, std::abs(nearestBranch(exact[1], target) - target));
    EXPECT_NEAR(std::abs((*e)[1] - target), nearest, 1e-6);
    EXPECT_LE(nearest, kPi / 2.0 + 1e-9);
  }
  EXPECT_THROW(p.solveWithin(Vec3::UnitZ(), -0.1, 0.0, 0.0), InputError);
}

TEST(TiltRotatePositioner, RefusesChainsThatAreNotTwoAxes)
{
  EXPECT_THROW(
      TiltRotatePositioner(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0")),
      InputError);
  const TiltRotatePositioner p = positioner();
  EXPECT_THROW(p.solveAll(Vec3::Zero()), InputError);
}

}  // namespace
}  // namespace spira
