#pragma once

#include "spira/kinematics/arm_configuration.h"
#include "spira/kinematics/joint_vector.h"

namespace spira {

// One inverse-kinematics solution of a 6R arm (URDF joints, rad).
struct IkSolution {
  JointVector q = JointVector::Zero();
  ArmConfiguration configuration;
  double limitMargin = 0.0;  // rad; negative when a joint is outside its limits
  bool withinLimits = false;
  double positionError = 0.0;     // mm, |p(q) - p_target| after refinement on the true chain
  double orientationError = 0.0;  // rad
  double dexterity = 0.0;         // dexterity.h, 0 at a singularity
};

}  // namespace spira
