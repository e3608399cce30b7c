// The FANUC ArcMate 120iC / M-20iA arm against the clean forward model (Chalvin's
// 004_bd0df31205c0c3c0.txt Appendix C.1 with the translation of M12 corrected), composed here from the thesis
// lengths in pendant joints:
//   Flange(J) = Rz(J1) Tx(d2) Ry(J2) Tz(d3) Ry(-(J2+J3)) Tz(d4) Rx(-J4) Tx(r4) Ry(-J5) Tx(r6) Rx(-J6) R_fp
// with R_fp = Ry(-90 deg) Rx(180 deg), d2 = 150, d3 = 790, d4 = 250, r4 = 835, r6 = 100 (mm). The
// bundled URDF read through the controller convention must agree everywhere, not only at the three
// check poses, and the closed-form IK must invert it in every configuration.
#include <gtest/gtest.h>

#include <random>

#include "robot_files.h"
#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"
#include "spira/kinematics/controller_convention.h"

namespace spira {
namespace {

Transform rot(double a, const Vec3& axis)
{
  return Transform(Eigen::AngleAxisd(a, axis));
}

Transform move(double x, double y, double z)
{
  Transform t = Transform::Identity();
  t.translation() = Vec3(x, y, z);
  return t;
}

Transform specFlange(const std::array<double, 6>& jDeg)
{
  double j[6];
  for (int i = 0; i < 6; ++i) j[i] = degToRad(jDeg[static_cast<size_t>(i)]);
  const Vec3 X = Vec3::UnitX(), Y = Vec3::UnitY(), Z = Vec3::UnitZ();
  const Transform fp = rot(degToRad(-90.0), Y) * rot(kPi, X);
  return rot(j[0], Z) * move(150, 0, 0) * rot(j[1], Y) * move(0, 0, 790) * rot(-(j[1] + j[2]), Y) *
         move(0, 0, 250) * rot(-j[3], X) * move(835, 0, 0) * rot(-j[4], Y) * move(100, 0, 0) * rot(-j[5], X) *
         fp;
}

TEST(FanucSpecModel, UrdfChainEqualsTheSpecCleanModelInPendantJoints)
{
  const ArmIk ik(KinematicChain::fromUrdfFile(test::robotUrdf("fanuc_m20ia"), "base", "tool0"));
  const ControllerConvention fc(Controller::FanucR30ib, ik.chain());
  // The clean model's three check poses first, here as whole matrices: W P R (180, -90, 0) at J = 0 is
  // R = Rz(0) Ry(-90) Rx(180).
  const Transform zero = ik.forward(fc.fromControllerDeg({{0, 0, 0, 0, 0, 0}}));
  EXPECT_LT((zero.translation() - Vec3(1085, 0, 1040)).norm(), 1e-9);
  const Mat3 wpr0 = (rot(degToRad(-90.0), Vec3::UnitY()) * rot(kPi, Vec3::UnitX())).linear();
  EXPECT_LT((zero.linear() - wpr0).norm(), 1e-12);
  const Transform down = ik.forward(fc.fromControllerDeg({{0, 0, 0, 0, -90, 0}}));
  EXPECT_LT((down.translation() - Vec3(985, 0, 940)).norm(), 1e-9);
  EXPECT_LT((down.linear() - rot(kPi, Vec3::UnitX()).linear()).norm(), 1e-12);  // W P R (180, 0, 0)

  std::mt19937 rng(120);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worstPosition = 0.0, worstRotation = 0.0;
  for (int k = 0; k < 2000; ++k) {
    // Table A.1 ranges (J3 relative to J2 kept moderate so the arm is not folded into itself).
    const std::array<double, 6> j{
        {170 * u(rng), 30 + 130 * u(rng), 60 * u(rng), 200 * u(rng), 135 * u(rng), 360 * u(rng)}};
    const Transform urdf = ik.forward(fc.fromControllerDeg(j));
    const Transform spec = specFlange(j);
    worstPosition = std::max(worstPosition, test::positionGap(urdf, spec));
    worstRotation = std::max(worstRotation, test::rotationGap(urdf, spec));

    // Every IK solution of the pose lands on it, and one of them is the drawn pendant vector.
    bool found = false;
    for (const IkSolution& s : ik.solveAll(spec)) {
      ASSERT_LT(test::positionGap(specFlange(fc.toControllerDeg(s.q)), spec), 1e-6);
      ASSERT_LT(test::rotationGap(specFlange(fc.toControllerDeg(s.q)), spec), 1e-8);
      const std::array<double, 6> back = fc.toControllerDeg(s.q);
      double gap = 0.0;
      for (size_t i = 0; i < 6; ++i) gap = std::max(gap, std::abs(wrapToPi(degToRad(back[i] - j[i]))));
      found = found || gap < 1e-7;
    }
    if (std::abs(j[4]) > 1.0) {
      EXPECT_TRUE(found) << k;
    }
  }
  EXPECT_LT(worstPosition, 1e-9);
  EXPECT_LT(worstRotation, 1e-12);
}

}  // namespace
}  // namespace spira
