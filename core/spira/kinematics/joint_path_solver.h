#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "spira/base/progress.h"
#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/controller_convention.h"
#include "spira/kinematics/tilt_rotate_positioner.h"
#include "spira/path/joint_trajectory.h"
#include "spira/path/trajectory.h"

namespace spira {

// How a deposition path (part frame) is placed in a robot cell for solving.
struct JointPathSetup {
  std::string cellName;
  Transform basePart = Transform::Identity();     // T_base_part, robot-only cells
  Transform flangeTcp = Transform::Identity();    // T_flange_tcp: the TCP in the arm's tip frame (tool0)
  double spinRad = 0.0;                           // free spin about the torch axis (tool_frame.h)
  std::optional<ArmConfiguration> configuration;  // held over the whole path; default: the seed's
  JointVector seed = JointVector::Zero();         // URDF joints the path starts from (unwrapping)
  // With a positioner, the part sits on its table at T_table_part and the positioner, mounted at
  // T_base_positioner in the robot base frame, turns every point's build direction to its vertical
  // (flat-position deposition); basePart is then ignored.
  const TiltRotatePositioner* positioner = nullptr;
  Transform basePositioner = Transform::Identity();
  Transform tablePart = Transform::Identity();
  Eigen::Vector2d positionerSeed = Eigen::Vector2d::Zero();
};

// Solves every point of `path` (TCP frames from toolFrame(point, spinRad)) in one arm configuration
// (path_tracker.h) and returns the joint trajectory in the controller's convention: axes in
// degrees, KUKA S/T or FANUC CONFIG per point, T_base_tcp, dexterity, and reachable = the pose is
// reached with every controller axis (and positioner axis) within its limits.
JointTrajectory solveJointTrajectory(const ArmIk& ik, const ControllerConvention& convention,
                                     const Trajectory& path, const JointPathSetup& setup, Progress& progress);

}  // namespace spira
