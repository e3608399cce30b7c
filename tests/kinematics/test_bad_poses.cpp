// Poses the inverse kinematics cannot take (issue 4, "Bad input"): NaN or infinite poses are refused
// with a clear error (naming the path point when there is one), never solved into garbage; poses out
// of reach are reported by index and never clipped.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "robot_files.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/kinematics/controller_convention.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/kinematics/path_tracker.h"
#include "spira/path/tool_frame.h"

namespace spira {
namespace {

ArmIk kuka()
{
  return ArmIk(KinematicChain::fromUrdfFile(test::robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
}

// A reachable pose of the KR 16: the flange 1200 mm out, 600 mm up, tool pointing down.
Transform reachable()
{
  Transform t = Transform::Identity();
  t.linear() = Eigen::AngleAxisd(kPi, Vec3::UnitY()).toRotationMatrix();
  t.translation() = Vec3(1200, 0, 600);
  return t;
}

// Runs `f`, expects an InputError and returns its message (with the hint checked non-empty).
template <class F>
std::string inputError(F&& f)
{
  try {
    f();
  } catch (const InputError& e) {
    EXPECT_FALSE(e.hint().empty()) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return std::string();
}

TEST(BadPoses, NanOrInfinitePosesAreRefusedWithAClearError)
{
  const ArmIk ik = kuka();
  ASSERT_FALSE(ik.solveAll(reachable()).empty());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Transform badPosition = reachable(), badRotation = reachable(), infinite = reachable();
  badPosition.translation().y() = nan;
  badRotation.linear()(1, 2) = nan;
  infinite.translation().z() = inf;
  for (const Transform& bad : {badPosition, badRotation, infinite}) {
    const std::string all = inputError([&] { ik.solveAll(bad); });
    EXPECT_NE(all.find("NaN or infinity"), std::string::npos) << all;
    const std::string one = inputError([&] { ik.solve(bad, ArmConfiguration{}, JointVector::Zero()); });
    EXPECT_NE(one.find("NaN or infinity"), std::string::npos) << one;
  }
  JointVector nanNear = JointVector::Zero();
  nanNear[4] = nan;
  const std::string near = inputError([&] { ik.solve(reachable(), ArmConfiguration{}, nanNear); });
  EXPECT_NE(near.find("NaN or infinity"), std::string::npos) << near;
}

TEST(BadPoses, APathWithANanPoseNamesItsIndex)
{
  const ArmIk ik = kuka();
  std::vector<Transform> poses;
  for (int k = 0; k < 10; ++k) {
    Transform t = reachable();
    t.translation().y() = 10.0 * k;
    poses.push_back(t);
  }
  const std::optional<IkSolution> first = ik.solve(poses[0], ArmConfiguration{}, JointVector::Zero());
  ASSERT_TRUE(first);
  NullProgress progress;
  ASSERT_NO_THROW(trackPath(ik, poses, Transform::Identity(), first->q, std::nullopt, progress));
  poses[7].translation().x() = std::nan("");
  const std::string what =
      inputError([&] { trackPath(ik, poses, Transform::Identity(), first->q, std::nullopt, progress); });
  EXPECT_NE(what.find("pose 7 "), std::string::npos) << what;

  // The same through the joint path solver, from a plan point with a NaN frame vector.
  const ControllerConvention convention(Controller::KukaKrc4, ik.chain());
  Trajectory path;
  for (int k = 0; k < 10; ++k) {
    TrajectoryPoint p;
    p.position = Vec3(0, 10.0 * k, 0);
    p.tangent = Vec3::UnitY();
    p.build = Vec3::UnitZ();
    p.normal = p.tangent.cross(p.build);
    path.points.push_back(p);
  }
  JointPathSetup setup;
  setup.basePart.translation() = Vec3(1200, 0, 250);
  setup.flangeTcp.translation() = Vec3(0, 0, 350);
  setup.seed = first->q;
  ASSERT_NO_THROW(solveJointTrajectory(ik, convention, path, setup, progress));
  path.points[4].build = Vec3(0, std::nan(""), 1);
  const std::string fromPlan =
      inputError([&] { solveJointTrajectory(ik, convention, path, setup, progress); });
  EXPECT_NE(fromPlan.find("pose 4 "), std::string::npos) << fromPlan;
}

TEST(BadPoses, UnreachablePosesAreReportedByIndexAndNeverClipped)
{
  const ArmIk ik = kuka();
  const ControllerConvention convention(Controller::KukaKrc4, ik.chain());
  Trajectory path;
  for (int k = 0; k < 30; ++k) {
    TrajectoryPoint p;
    p.position = Vec3(0, 5.0 * k, 0);
    // Points 11-13 lie 2.5 m further out: beyond the KR 16's 1.6 m reach.
    if (k >= 11 && k <= 13) p.position.x() = 2500.0;
    p.tangent = Vec3::UnitY();
    p.build = Vec3::UnitZ();
    p.normal = p.tangent.cross(p.build);
    path.points.push_back(p);
  }
  JointPathSetup setup;
  setup.basePart.translation() = Vec3(1200, 0, 250);
  setup.flangeTcp.translation() = Vec3(0, 0, 350);
  const std::optional<IkSolution> first =
      ik.solve(setup.basePart * toolFrame(path.points[0], 0.0) * setup.flangeTcp.inverse(),
               ArmConfiguration{}, JointVector::Zero());
  ASSERT_TRUE(first);
  setup.seed = first->q;
  NullProgress progress;
  const JointTrajectory joints = solveJointTrajectory(ik, convention, path, setup, progress);
  ASSERT_EQ(joints.size(), path.size());
  for (size_t i = 0; i < path.size(); ++i) {
    const bool out = i >= 11 && i <= 13;
    EXPECT_EQ(joints.points[i].reachable, !out) << i;
    const Transform reached =
        ik.forward(convention.fromControllerDeg(joints.points[i].robotDeg)) * setup.flangeTcp;
    const Vec3 target = (setup.basePart * path.points[i].position);
    if (out) {
      // Not moved towards the target and left there: the previous point's joints are repeated.
      EXPECT_EQ(joints.points[i].robotDeg, joints.points[10].robotDeg) << i;
      EXPECT_GT((reached.translation() - target).norm(), 800.0) << i;
    } else {
      EXPECT_LT((reached.translation() - target).norm(), 1e-6) << i;
    }
  }
}

}  // namespace
}  // namespace spira
