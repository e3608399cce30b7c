#include <gtest/gtest.h>

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
    // Spec Eq. C.24-C.25: q7 = atan2(sqrt(bx^2 + by^2), bz), q8 = atan2(by, -bx), and
    // Ry(q7) Rz(q8) b = z; it is the first (e1 >= 0) branch here.
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
