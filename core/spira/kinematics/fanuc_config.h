#pragma once

#include <array>
#include <optional>
#include <string>

#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/opw_model.h"

namespace spira {

// The FANUC position CONFIG 'F/N U/D T/B, t1, t4, t6' of an arm pose (R-30iB TP / LS files):
//   F/N  wrist flip: F when J5 >= 0, N when J5 < 0 (RoboDK's generic FANUC post processor,
//        Fanuc_R30iA.py, add_target_cartesian: "F means axis 5 >= 0, N means axis 5 < 0"; the
//        usual N pose of the M-20iA has the flange tilted down with J5 = -90).
//   U/D  elbow up/down: U when the elbow angle from the stretched arm is >= 0 in the arm's OPW
//        form, i.e. bent as at the all-zero pose (arm_configuration.h "up").
//   T/B  T when the wrist centre is in front of the J1 axis, B behind it.
//   t1, t4, t6  turn numbers of J1, J4, J6: 0 for -180 < J < 180, +1 for 180 <= J < 540,
//        -1 for -540 < J <= -180 (the same post processor's angle_2_turn).
// Joint values are the pendant's (J3 = q3 - q2). Derived from the URDF model; verify on a
// controller before relying on a CONFIG to pick a branch.
struct FanucConfig {
  bool flip = false;
  bool up = true;
  bool front = true;
  std::array<int, 3> turns{};  // J1, J4, J6

  bool operator==(const FanucConfig& o) const
  {
    return flip == o.flip && up == o.up && front == o.front && turns == o.turns;
  }
  bool operator!=(const FanucConfig& o) const { return !(*this == o); }
  // "N U T, 0, 0, 0"; parse accepts the same text (spaces optional) and throws InputError otherwise.
  std::string format() const;
  static FanucConfig parse(const std::string& text);
};

int fanucTurnNumber(double deg);
FanucConfig fanucConfig(const OpwModel& model, const JointVector& q);

// The joint vector that reaches T_base_tip with this CONFIG within the IK's limits, or nothing.
// The CONFIG does not fix J3's turn (its range spans 458 deg): J3 comes back in (-180, 180] when
// that is within the limits.
std::optional<JointVector> fanucJointsFrom(const ArmIk& ik, const Transform& baseTip,
                                           const FanucConfig& config);

}  // namespace spira
