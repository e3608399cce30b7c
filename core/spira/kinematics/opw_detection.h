#pragma once

#include <string>

#include "spira/kinematics/kinematic_chain.h"
#include "spira/kinematics/opw_model.h"

namespace spira {

// The result of reading a chain as an ortho-parallel 6R arm with a spherical wrist.
struct OpwDetection {
  bool ok = false;
  std::string reason;  // why not, when !ok (one sentence, names the joints at fault)
  OpwModel model;
  double maxPositionError = 0.0;     // mm, OPW model vs chain on the verification samples
  double maxOrientationError = 0.0;  // rad
};

// Derives the OPW form of `chain` from its geometry at the zero pose, with nothing known about
// the robot in advance: axis 1 gives the OPW z (signed to point up in the base frame) and origin
// (the foot of the base origin on axis 1); axis 2 gives y, signed so that a1 >= 0; joint signs
// follow from the chain's axes, offsets from the zero-pose angles of the upper arm, forearm and
// wrist; any tip rotation about the flange axis goes into offset 6, any other into T_flange_tip.
// The model is then checked against the chain's own forward kinematics on random joint vectors.
// Requirements checked: 6 revolute joints, axis 1 perpendicular to axis 2, axes 2 and 3 parallel,
// axes 4, 5 and 6 through one point, axis 5 perpendicular to axes 4 and 6, axis 4 perpendicular
// to axis 2.
OpwDetection detectOpw(const KinematicChain& chain);

}  // namespace spira
