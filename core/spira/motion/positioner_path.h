#pragma once

#include <vector>

#include <Eigen/Core>

#include "spira/base/progress.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/motion/motion_params.h"
#include "spira/path/trajectory.h"

namespace spira {

// The positioner's axes along a path (URDF rad, index-aligned with it).
struct PositionerPath {
  std::vector<Eigen::Vector2d> axes;
  // The positioner brought the build direction within params.buildTiltToleranceDeg of its
  // vertical; where not, the axes repeat the previous point's.
  std::vector<bool> reached;
};

// Turns every point's build direction to within params.buildTiltToleranceDeg of the positioner's
// vertical (TiltRotatePositioner::solveWithin). The rotation aims at a smooth target: the previous
// point's rotation, less the point's turn about the rotation axis when params.turntableFollowsPoint
// (the table turns the part under the torch), and is moved off it only as far as the tolerance
// demands; the tilt then brings the build direction as close to the vertical as it can. Needs
// setup.positioner.
PositionerPath placeOnPositioner(const Trajectory& path, const JointPathSetup& setup,
                                 const MotionParams& params, Progress& progress);

}  // namespace spira
