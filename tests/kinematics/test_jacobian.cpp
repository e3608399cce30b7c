#include <gtest/gtest.h>

#include <random>

#include <Eigen/SVD>

#include "robot_files.h"
#include "spira/base/units.h"
#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/dexterity.h"
#include "spira/kinematics/jacobian.h"

namespace spira {
namespace {

using test::robotUrdf;

JointVector deg(double a, double b, double c, double d, double e, double f)
{
  JointVector q;
  q << degToRad(a), degToRad(b), degToRad(c), degToRad(d), degToRad(e), degToRad(f);
  return q;
}

TEST(Jacobian, MatchesFiniteDifferencesOfTheForwardKinematics)
{
  const KinematicChain c = KinematicChain::fromUrdfFile(robotUrdf("fanuc_m20ia"), "base_link", "tool0");
  const Vec3 point(30, -20, 250);  // a TCP 250 mm out of the flange, off axis
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  const double h = 1e-6;
  for (int k = 0; k < 50; ++k) {
    JointVector q;
    for (int i = 0; i < 6; ++i) q[i] = u(rng);
    const Jacobian j = geometricJacobian(c, q, point);
    ASSERT_EQ(j.cols(), 6);
    for (int i = 0; i < 6; ++i) {
      JointVector qp = q, qm = q;
      qp[i] += h;
      qm[i] -= h;
      const Transform tp = c.forward(qp), tm = c.forward(qm);
      const Vec3 v = (tp * point - tm * point) / (2 * h);
      const Eigen::AngleAxisd w(tp.linear() * tm.linear().transpose());
      EXPECT_NEAR((j.col(i).head<3>() - v).norm(), 0.0, 1e-5 * (1.0 + v.norm()));
      EXPECT_NEAR((j.col(i).tail<3>() - w.axis() * w.angle() / (2 * h)).norm(), 0.0, 1e-7);
    }
  }
}

// Independent reference: the ratio from a full SVD of each block.
double svdRatio(const Mat3& m)
{
  const Vec3 s = Eigen::JacobiSVD<Mat3>(m).singularValues();
  return s[2] / s[0];
}

TEST(Dexterity, BlockRatiosAtTheWristCentre)
{
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  const JointVector q = deg(20, -80, 100, 30, 50, -40);
  const Jacobian j = geometricJacobian(ik.chain(), q, ik.model().wristCentreInTip());
  // The wrist joints do not move the wrist centre: the upper-right block vanishes.
  EXPECT_LT((j.block<3, 3>(0, 3).norm()), 1e-9);
  const Eigen::Matrix<double, 6, 6> j6 = j;
  const double expected = std::min(svdRatio(j6.block<3, 3>(0, 0)), svdRatio(j6.block<3, 3>(3, 3)));
  EXPECT_NEAR(armDexterity(j6), expected, 1e-12);
  EXPECT_NEAR(ik.dexterity(q), expected, 1e-12);
  EXPECT_GT(expected, 0.05);
  EXPECT_LE(expected, 1.0);
  // The wrist block holds axes 4, 5, 6: axis 5 is perpendicular to both, axes 4 and 6 meet at the
  // angle A5, so C^T C has eigenvalues 1, 1 + cos A5, 1 - cos A5 and the ratio is tan(A5 / 2).
  EXPECT_NEAR(svdRatio(j6.block<3, 3>(3, 3)), std::tan(degToRad(25)), 1e-12);
}

TEST(Dexterity, ZeroAtEachKindOfSingularity)
{
  const ArmIk ik(KinematicChain::fromUrdfFile(robotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  // Wrist: A5 = 0 lines up axes 4 and 6.
  EXPECT_LT(ik.dexterity(deg(20, -80, 100, 30, 0, -40)), 1e-7);
  // Elbow: stretched arm, A3 = -atan(35/670).
  EXPECT_LT(ik.dexterity(deg(20, -80, -radToDeg(std::atan2(35.0, 670.0)), 30, 50, -40)), 1e-7);
  // Shoulder: upper arm vertical (A2 = -90) and forearm bent so the wrist centre is on axis 1:
  // 260 + 671.5 sin(E) = 0 with E = A3 + atan(35/670) the elbow angle.
  const double elbow = std::asin(-260.0 / std::hypot(35.0, 670.0));
  const JointVector shoulder = deg(20, -90, radToDeg(elbow - std::atan2(35.0, 670.0)), 30, 50, -40);
  const Vec3 w = ik.wristCentre(shoulder);
  EXPECT_NEAR(std::hypot(w.x(), w.y()), 0.0, 1e-9);
  EXPECT_LT(ik.dexterity(shoulder), 1e-7);
  // And away from them it is not.
  EXPECT_GT(ik.dexterity(deg(20, -80, 100, 30, 50, -40)), 0.05);
}

}  // namespace
}  // namespace spira
