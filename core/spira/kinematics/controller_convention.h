#pragma once

#include <array>
#include <string>

#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/joint_vector.h"
#include "spira/kinematics/kinematic_chain.h"
#include "spira/path/joint_trajectory.h"

namespace spira {

enum class Controller {
  KukaKrc4,    // KRL axes A1..A6: A_n = q_n in degrees (the KUKA URDFs carry KUKA's senses)
  FanucR30ib,  // TP axes J1..J6: J_n = q_n in degrees except J3 = q3 - q2 (J2/J3 linkage)
  AbbIrc5      // RAPID axes rax_1..rax_6 of a serial arm: rax_n = q_n in degrees
};

// A robot controller's joint convention over a 6R chain whose URDF joints follow the
// ROS-Industrial support packages (see resources/robots/README.md for the evidence):
//   KUKA KR C4: no signs, offsets or couplings; only radians -> degrees
//     (kuka_experimental's RSI/EKI drivers convert units only).
//   FANUC R-30iB: J3 on the pendant is the forearm angle from the horizontal, so
//     joint_3 = J3 + J2 and J3 = q3 - q2 (fanuc_driver's J23_factor = 1 for the M-20iA,
//     fanuc_utils.h "J3_out = J3_in + j23_factor * J2_in"). The J3 range applies to that J3.
//   ABB IRC5 (serial arms such as the IRB 1600): only radians -> degrees (abb_driver converts units
//     and compensates J2/J3 only for parallel-linkage arms, its J23_coupled option, off by default).
class ControllerConvention {
 public:
  ControllerConvention(Controller controller, const KinematicChain& chain);

  // "kuka_krc4" / "fanuc_r30ib" / "abb_irc5" (the JointTrajectory::controller ids). parse throws
  // InputError.
  static std::string id(Controller controller);
  static Controller parse(const std::string& id);

  Controller controller() const { return controller_; }
  std::string id() const { return id(controller_); }

  // URDF joints (rad) -> controller axes (deg), and back.
  std::array<double, 6> toControllerDeg(const JointVector& q) const;
  JointVector fromControllerDeg(const std::array<double, 6>& deg) const;

  // Axis limits in controller axes (names A1..A6, J1..J6 or rax_1..rax_6, deg, deg/s), from the chain's
  // limits.
  const std::array<AxisLimit, 6>& axisLimits() const { return limits_; }
  // Distance of each controller axis to its limits, rad (negative outside), and the smallest.
  JointVector axisMargins(const JointVector& q) const;
  double limitMargin(const JointVector& q) const { return axisMargins(q).minCoeff(); }
  // Makes the IK flag solutions against these limits instead of the URDF boxes.
  void applyTo(ArmIk& ik) const;

  // Fills point.robotDeg and the configuration fields (KUKA S/T, the FANUC CONFIG string or ABB's
  // confdata).
  void describe(const OpwModel& model, const JointVector& q, JointPoint& point) const;

 private:
  Controller controller_;
  std::array<AxisLimit, 6> limits_{};
};

}  // namespace spira
