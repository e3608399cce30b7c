#pragma once

#include <array>

#include "spira/base/transform.h"
#include "spira/kinematics/arm_configuration.h"
#include "spira/kinematics/joint_vector.h"

namespace spira {

// The OPW parameters of an ortho-parallel 6R arm with a spherical wrist (Brandstoetter, Angerer,
// Hofbaur, "An analytical solution of the inverse kinematics problem of industrial serial
// manipulators with an ortho-parallel basis and a spherical wrist", 2014), in the convention of
// the ROS-Industrial opw_kinematics parameter files: theta_i = signs_i * q_i - offsets_i, where
// q is the URDF joint vector and theta the OPW angle. At theta = 0 the arm points straight up
// (axis 1 = z, axes 2, 3 = y), the wrist centre is at (a1 + a2, b, c1 + c2 + c3) and the flange,
// c4 further along z, has the identity orientation. Lengths in mm, angles in rad.
struct OpwParameters {
  double a1 = 0.0, a2 = 0.0, b = 0.0, c1 = 0.0, c2 = 0.0, c3 = 0.0, c4 = 0.0;
  std::array<int, 6> signs{{1, 1, 1, 1, 1, 1}};
  std::array<double, 6> offsets{};
};

// A chain written in OPW form: T_base_tip(q) = T_base_opw * F_opw(theta(q)) * T_flange_tip, with
// F_opw the OPW forward kinematics. Built by detectOpw() (opw_detection.h) from a chain's geometry.
class OpwModel {
 public:
  OpwModel() = default;
  OpwModel(const OpwParameters& parameters, const Transform& baseOpw, const Transform& flangeTip);

  const OpwParameters& parameters() const { return p_; }
  const Transform& baseOpw() const { return baseOpw_; }      // T_base_opw
  const Transform& flangeTip() const { return flangeTip_; }  // T_flange_tip
  // The wrist centre (intersection of axes 4, 5, 6) in the tip frame: fixed there.
  Vec3 wristCentreInTip() const;

  JointVector toOpw(const JointVector& q) const;
  JointVector fromOpw(const JointVector& theta) const;

  // T_opw_flange of OPW angles, and T_base_tip of URDF joints.
  Transform opwFlange(const JointVector& theta) const;
  Transform forward(const JointVector& q) const;

  // x of the wrist centre in the frame that turns with joint 1 (negative: behind axis 1).
  double wristReach(const JointVector& theta) const;
  // The elbow angle from the stretched arm, wrapped to (-pi, pi].
  double elbowAngle(const JointVector& theta) const;
  ArmConfiguration configurationOf(const JointVector& q) const;
  // URDF joint 3 value at which the arm is stretched (elbow angle 0), e.g. -2.99 deg on the KR 16.
  double stretchedJoint3() const { return p_.signs[2] * (p_.offsets[2] - psi3_); }

  // The closed-form solution of one configuration for T_opw_flange, as OPW angles. False when the
  // pose is out of reach for that configuration. At a wrist singularity (theta5 = 0) theta4 is
  // set to `theta4Hint` and theta6 takes the rest.
  bool solve(const Transform& opwFlange, const ArmConfiguration& configuration, double theta4Hint,
             JointVector& theta) const;

 private:
  OpwParameters p_;
  Transform baseOpw_ = Transform::Identity();
  Transform flangeTip_ = Transform::Identity();
  Transform baseOpwInverse_ = Transform::Identity();
  Transform flangeTipInverse_ = Transform::Identity();
  double psi3_ = 0.0;  // atan2(a2, c3): forearm offset angle
  double k_ = 0.0;     // hypot(a2, c3): axis 3 to wrist centre

  friend class ArmIk;
};

}  // namespace spira
