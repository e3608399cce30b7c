// The head's inverse kinematics checked against its forward kinematics (the two formulas are
// independent: FK multiplies the rotations, IK solves two cones), and against poses worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "export_gcode/gcode_machine.h"
#include "export_gcode/head_kinematics.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "support/test_support.h"

namespace spira {
namespace {

GcodeMachine bundledMachine()
{
  return readMachineFile(test::sourceDir() / "resources" / "machines" / "gantry_ca_head.machine");
}

// A B/C head with the axes offset from each other and a bent torch, so no term of FK vanishes.
GcodeMachine offsetBcMachine()
{
  GcodeMachine m = bundledMachine();
  m.rotary[0] = {"C", Vec3::UnitZ(), -3600.0, 3600.0};
  m.rotary[1] = {"B", Vec3(0.1, 1.0, 0.2).normalized(), -170.0, 170.0};
  m.firstToSecond = Vec3(12.0, -7.0, -40.0);
  m.secondToTip = Vec3(25.0, 5.0, -180.0);
  m.toolDirection = Vec3(0.2, 0.0, -1.0).normalized();
  for (auto& a : m.linear) {
    a.minMm = -1e6;
    a.maxMm = 1e6;
  }
  return m;
}

double angleDeg(const Vec3& a, const Vec3& b)
{
  return radToDeg(std::atan2(a.cross(b).norm(), a.dot(b)));
}

std::string name(size_t i)
{
  return "pose " + std::to_string(i);
}

void expectRoundTrip(const GcodeMachine& m, unsigned seed, double maxTiltDeg)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<HeadPose> poses;
  // A reachable direction is the forward image of random angles; the tips are random points.
  for (int i = 0; i < 3000; ++i) {
    HeadAxes a;
    a.rotaryDeg = {180.0 * u(rng), maxTiltDeg * u(rng)};
    HeadPose p = headForward(m, a);
    p.tip = Vec3(100.0 * u(rng), 100.0 * u(rng), 50.0 + 50.0 * u(rng));
    poses.push_back(p);
  }
  const std::vector<HeadAxes> axes = solveHeadPath(m, poses, name);
  ASSERT_EQ(axes.size(), poses.size());
  double worstMm = 0.0, worstDeg = 0.0;
  for (size_t i = 0; i < poses.size(); ++i) {
    const HeadPose back = headForward(m, axes[i]);
    worstMm = std::max(worstMm, (back.tip - m.partOrigin - poses[i].tip).norm());
    worstDeg = std::max(worstDeg, angleDeg(back.axis, poses[i].axis));
    for (size_t k = 0; k < 2; ++k) {
      EXPECT_GE(axes[i].rotaryDeg[k], m.rotary[k].minDeg);
      EXPECT_LE(axes[i].rotaryDeg[k], m.rotary[k].maxDeg);
    }
  }
  EXPECT_LT(worstMm, 1e-9);
  EXPECT_LT(worstDeg, 1e-9);
  std::printf("head IK round trip: worst %.3g mm, %.3g deg\n", worstMm, worstDeg);
}

TEST(HeadKinematics, ForwardOfInverseIsThePoseOnTheBundledHead)
{
  expectRoundTrip(bundledMachine(), 7u, 95.0);
}

TEST(HeadKinematics, ForwardOfInverseIsThePoseOnAnOffsetSkewHead)
{
  expectRoundTrip(offsetBcMachine(), 11u, 170.0);
}

TEST(HeadKinematics, AVerticalTorchIsAtZeroAnglesAbovethePivotOffset)
{
  const GcodeMachine m = bundledMachine();
  const std::vector<HeadAxes> a = solveHeadPath(m, {{Vec3(10.0, -20.0, 30.0), -Vec3::UnitZ()}}, name);
  EXPECT_NEAR(a[0].rotaryDeg[0], 0.0, 1e-12);
  EXPECT_NEAR(a[0].rotaryDeg[1], 0.0, 1e-12);
  // The pivot sits 150 mm above the tip; the part origin is at (400, 300, 20).
  EXPECT_NEAR(a[0].linear.x(), 410.0, 1e-12);
  EXPECT_NEAR(a[0].linear.y(), 280.0, 1e-12);
  EXPECT_NEAR(a[0].linear.z(), 200.0, 1e-12);
}

TEST(HeadKinematics, ATorchTiltedAboutXIsATiltWithThePivotSwungBack)
{
  const GcodeMachine m = bundledMachine();
  // Rx(30 deg) turns (0, 0, -1) into (0, sin 30, -cos 30); the pivot is 150 mm back along it.
  const Vec3 axis(0.0, 0.5, -std::sqrt(3.0) / 2.0);
  const std::vector<HeadAxes> a = solveHeadPath(m, {{Vec3::Zero(), axis}}, name);
  EXPECT_NEAR(a[0].rotaryDeg[0], 0.0, 1e-9);
  EXPECT_NEAR(a[0].rotaryDeg[1], 30.0, 1e-9);
  EXPECT_NEAR(a[0].linear.x(), 400.0, 1e-9);
  EXPECT_NEAR(a[0].linear.y(), 300.0 - 75.0, 1e-9);
  EXPECT_NEAR(a[0].linear.z(), 20.0 + 150.0 * std::sqrt(3.0) / 2.0, 1e-9);
}

TEST(HeadKinematics, CUnwrapsRoundAndAKeepsItsSignThroughTheVertical)
{
  const GcodeMachine m = bundledMachine();
  std::vector<HeadPose> poses;
  // Three turns of a torch leaning 20 deg, its lean turning with the path.
  for (int i = 0; i <= 3 * 36; ++i) {
    const double phi = degToRad(10.0 * i), tilt = degToRad(20.0);
    poses.push_back({Vec3::Zero(),
                     Vec3(std::sin(tilt) * std::cos(phi), std::sin(tilt) * std::sin(phi), -std::cos(tilt))});
  }
  std::vector<HeadAxes> a = solveHeadPath(m, poses, name);
  for (size_t i = 1; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].rotaryDeg[0] - a[i - 1].rotaryDeg[0], 10.0, 1e-9) << i;
    EXPECT_NEAR(a[i].rotaryDeg[1], a[0].rotaryDeg[1], 1e-9) << i;
  }
  EXPECT_NEAR(std::abs(a[0].rotaryDeg[1]), 20.0, 1e-9);
  // A lean swinging from +y through the vertical to -y: A changes sign, C stays.
  poses.clear();
  for (int i = -10; i <= 10; ++i) {
    const double tilt = degToRad(2.0 * i);
    poses.push_back({Vec3::Zero(), Vec3(0.0, std::sin(tilt), -std::cos(tilt))});
  }
  a = solveHeadPath(m, poses, name);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].rotaryDeg[0], 0.0, 1e-9) << i;
    EXPECT_NEAR(a[i].rotaryDeg[1], 2.0 * (static_cast<double>(i) - 10.0), 1e-9) << i;
  }
}

TEST(HeadKinematics, AnUprightToleranceHoldsASlightLeanAtZeroTilt)
{
  const GcodeMachine m = bundledMachine();
  const double lean = degToRad(0.5);
  std::vector<HeadPose> poses;
  for (int i = 0; i < 8; ++i) {
    const double phi = degToRad(45.0 * i);
    poses.push_back({Vec3::Zero(),
                     Vec3(std::sin(lean) * std::cos(phi), std::sin(lean) * std::sin(phi), -std::cos(lean))});
  }
  const std::vector<HeadAxes> exact = solveHeadPath(m, poses, name);
  EXPECT_NEAR(std::abs(exact[3].rotaryDeg[1]), 0.5, 1e-9);
  EXPECT_NEAR(exact[3].rotaryDeg[0] - exact[0].rotaryDeg[0], 135.0, 1e-9);
  const std::vector<HeadAxes> upright = solveHeadPath(m, poses, name, 1.0);
  for (const HeadAxes& a : upright) {
    EXPECT_EQ(a.rotaryDeg[0], 0.0);
    EXPECT_EQ(a.rotaryDeg[1], 0.0);
  }
  // 0.4 deg is beyond a 0.3 deg tolerance: followed exactly.
  EXPECT_NEAR(std::abs(solveHeadPath(m, poses, name, 0.4)[0].rotaryDeg[1]), 0.5, 1e-9);
}

TEST(HeadKinematics, PosesOutsideTheLimitsAreRefusedWithThePointAndTheAxis)
{
  const GcodeMachine m = bundledMachine();
  const double tilt = degToRad(100.0);
  try {
    solveHeadPath(
        m, {{Vec3::Zero(), -Vec3::UnitZ()}, {Vec3::Zero(), Vec3(0.0, std::sin(tilt), -std::cos(tilt))}},
        name);
    FAIL() << "a 100 deg tilt passed an A limited to 95 deg";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pose 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("A = "), std::string::npos) << e.what();
  }
  try {
    solveHeadPath(m, {{Vec3(500.0, 0.0, 0.0), -Vec3::UnitZ()}}, name);
    FAIL() << "X = 900 passed an X limited to 800";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pose 0: X = 900"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spira
