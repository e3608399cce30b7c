#pragma once

#include <vector>

#include <Eigen/Core>

#include "spira/base/progress.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/motion/motion_params.h"
#include "spira/path/trajectory.h"

namespace spira {

// Everything about a path placed in a cell that does not depend on the torch spin, computed once
// before the spin is chosen. Index-aligned with the path.
//
// The spin chart. tool_frame.h measures the spin from the travel direction, which turns a full
// turn per revolution; a low-degree polynomial per layer (Chalvin Eq. 4.1) is better set in a
// frame that does not. So the optimiser's spin value c is measured from a reference x axis fixed
// in the robot base frame: at point m the reference x is the base frame's reference axis turned
// by the smallest rotation that takes the reference torch axis (the mean torch axis of the path)
// onto this point's torch axis. For a vertical torch that is a fixed horizontal direction,
// Chalvin's R_Z of the Bryant angles. The TCP frame at chart value c is
//   T_base_tcp = baseTcp0[m] * Rz(chartOffset[m] + c),  i.e. tool_frame spin = chartOffset[m] + c.
struct MotionFrames {
  std::vector<Transform> baseTcp0;        // T_base_tcp of toolFrame(point, 0) at the part's pose
  std::vector<double> chartOffset;        // rad, unwrapped along the path
  std::vector<Eigen::Vector2d> external;  // positioner axes (URDF rad), zero without a positioner
  // The positioner could turn the build direction vertical, within params.buildTiltToleranceDeg
  // (true without one); its limits are checked with the rest (motion_checks.h).
  std::vector<bool> positionerReached;
  Vec3 referenceAxis = -Vec3::UnitZ();  // base frame: the chart's reference torch axis
};

// Places every point (JointPathSetup: fixed part, or positioner keeping the build direction
// vertical, placeOnPositioner in positioner_path.h) and builds the chart.
MotionFrames buildMotionFrames(const Trajectory& path, const JointPathSetup& setup,
                               const MotionParams& params, Progress& progress);

// Rz(angle): the turn of a TCP frame about its own z (the torch axis).
Transform spinAboutTorch(double angle);

}  // namespace spira
