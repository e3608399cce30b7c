#pragma once

#include <limits>
#include <string>

#include "spira/base/transform.h"

namespace spira {

// One revolute joint of a KinematicChain. `origin` is T_prev_joint: the joint frame in the frame of
// the previous joint after its rotation (or in the chain's base frame for the first joint), with
// every fixed joint in between folded in. Lengths in mm, angles in rad, speeds in rad/s.
struct ChainJoint {
  std::string name;
  Transform origin = Transform::Identity();
  Vec3 axis = Vec3::UnitZ();  // unit vector in the joint frame
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double maxVelocity = std::numeric_limits<double>::infinity();
};

}  // namespace spira
