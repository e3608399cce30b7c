#include <gtest/gtest.h>

#include <cmath>

#include "robot_files.h"
#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"
#include "spira/kinematics/path_tracker.h"

namespace spira {
namespace {

using test::positionGap;
using test::robotUrdf;
using test::rotationGap;

Transform translation(double x, double y, double z)
{
  Transform t = Transform::Identity();
  t.translation() = Vec3(x, y, z);
  return t;
}

// TCP poses round a horizontal circle, torch down (z = -Z), x along the travel: over one lap the
// tool turns a full revolution about the vertical.
std::vector<Transform> circle(const Vec3& centre, double radius, int steps, double laps)
{
  std::vector<Transform> out;
  for (int k = 0; k <= steps; ++k) {
    const double a = 2 * kPi * laps * k / steps;
    Transform t = Transform::Identity();
    const Vec3 x(-std::sin(a), std::cos(a), 0), z(0, 0, -1);
    t.linear().col(0) = x;
    t.linear().col(1) = z.cross(x);
    t.linear().col(2) = z;
    t.translation() = centre + radius * Vec3(std::cos(a), std::sin(a), 0);
    out.push_back(t);
  }
  return out;
}

TEST(PathTracker, CircleKeepsTheConfigurationAndUnwindsJointSix)
{
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  const Transform flangeTcp = translation(0, 0, 250);  // torch 250 mm along tool0 z
  const std::vector<Transform> poses = circle(Vec3(1100, 0, 400), 200, 720, 1.0);
  ArmConfiguration config;  // front / up / noflip
  const std::optional<IkSolution> first =
      ik.solve(poses[0] * flangeTcp.inverse(), config, JointVector::Zero());
  ASSERT_TRUE(first);
  NullProgress progress;
  const PathTrack track = trackPath(ik, poses, flangeTcp, first->q, config, progress);
  ASSERT_EQ(track.poses.size(), poses.size());
  EXPECT_EQ(track.unreachable, 0u);
  EXPECT_EQ(track.configuration, config);
  for (size_t i = 0; i < poses.size(); ++i) {
    const TrackedPose& p = track.poses[i];
    ASSERT_TRUE(p.reachable);
    ASSERT_EQ(ik.configurationOf(p.q), config) << i;
    const Transform tcp = ik.forward(p.q) * flangeTcp;
    ASSERT_LT(positionGap(tcp, poses[i]), 1e-9);
    ASSERT_LT(rotationGap(tcp, poses[i]), 1e-12);
    EXPECT_GT(p.dexterity, 0.0);
  }
  // Half-degree steps of the path never move a joint by more than 3 degrees.
  EXPECT_LT(radToDeg(track.maxJointStep), 3.0);
  EXPECT_GT(radToDeg(track.maxJointStep), 0.1);
  // One lap later the arm is back where it started except joint 6, one full turn further on:
  // continuous through +-180 deg instead of jumping back.
  const JointVector& a = track.poses.front().q;
  const JointVector& b = track.poses.back().q;
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(b[i], a[i], 1e-9) << i;
  EXPECT_NEAR(std::abs(b[5] - a[5]), 2 * kPi, 1e-9);
}

TEST(PathTracker, ConfigurationDefaultsToTheSeedsAndUnreachablePosesAreReported)
{
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  std::vector<Transform> poses = circle(Vec3(1100, 0, 400), 150, 40, 0.25);
  poses[20].translation() = Vec3(4000, 0, 400);  // far out of reach
  ArmConfiguration down;
  down.up = false;
  const std::optional<IkSolution> first = ik.solve(poses[0], down, JointVector::Zero());
  ASSERT_TRUE(first);
  NullProgress progress;
  const PathTrack track = trackPath(ik, poses, Transform::Identity(), first->q, std::nullopt, progress);
  EXPECT_EQ(track.configuration, down);
  EXPECT_EQ(track.unreachable, 1u);
  EXPECT_FALSE(track.poses[20].reachable);
  EXPECT_EQ(track.poses[20].q, track.poses[19].q);
  EXPECT_TRUE(track.poses[21].reachable);
  EXPECT_EQ(ik.configurationOf(track.poses[21].q), down);
}

TEST(PathTracker, ObeysCancellation)
{
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  CallbackProgress progress;
  progress.cancel();
  EXPECT_THROW(trackPath(ik, circle(Vec3(1100, 0, 400), 150, 10, 1.0), Transform::Identity(),
                         JointVector::Zero(), std::nullopt, progress),
               Cancelled);
}

}  // namespace
}  // namespace spira
