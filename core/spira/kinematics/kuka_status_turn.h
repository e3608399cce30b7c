#pragma once

#include <optional>

#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/opw_model.h"

namespace spira {

// KRL Status (S) and Turn (T) of a KUKA arm pose, as KUKA defines them for its 6-axis arms
// (KUKA System Software 8.x "Operating and Programming Instructions for System Integrators",
// section on Status and Turn; the same wording is quoted in robot-forum.com thread 7173
// "x value of wrist root point" and discussed in thread 45777 "KUKA status bit flip/no-flip"):
//   S bit 0  the wrist root point (intersection of A4, A5, A6) has a negative x in the A1
//            coordinate system (the $ROBROOT frame turning with A1): overhead area.
//   S bit 1  A3 >= phi, where phi is the A3 angle of the stretched arm (0 when axes 3 and 4
//            intersect; -2.99 deg on the KR 16 with its 35 mm forearm offset).
//   S bit 2  -180 <= A5 < 0 or A5 >= 180 deg (the manual's table; A5 = 0 itself gives 0).
//   T bit n  axis A(n+1) < 0 deg, n = 0..5.
// Here A_n = q_n in degrees (controller_convention.h). Checked on the URDF model only, not on a
// controller.
struct KukaStatusTurn {
  int status = 0;
  int turn = 0;
};

KukaStatusTurn kukaStatusTurn(const OpwModel& model, const JointVector& q);

// The joint vector that reaches T_base_tip with Status `status` and Turn `turn` within the IK's
// limits, or nothing (out of reach, or no in-limit joint vector with those bits).
std::optional<JointVector> kukaJointsFrom(const ArmIk& ik, const Transform& baseTip, int status, int turn);

}  // namespace spira
