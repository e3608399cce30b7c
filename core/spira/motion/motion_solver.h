#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/controller_convention.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/motion/motion_params.h"
#include "spira/motion/motion_report.h"
#include "spira/path/joint_trajectory.h"
#include "spira/path/trajectory.h"

namespace spira {

struct MotionResult {
  JointTrajectory joints;       // controller convention, index-aligned with the path
  std::vector<double> spinRad;  // the tool_frame.h spin of every point (its TCP frame's turn)
  MotionReport report;
};

// Solves the robot (and positioner) motion of a deposition path in a cell and checks it.
// The placement, tool, configuration and seed come from `setup` (joint_path_solver.h; its
// spinRad is the spin at the first point). Every point is solved in one arm configuration with
// each joint on the 2 pi branch nearest the previous point (trackPath), first with a constant
// spin (params.constantSpin), then, if params.optimiseSpin, with the layer-wise optimised spin
// (spin_optimiser.h). The optimised plan is returned unless it costs more (objective plus
// constraint penalties, spin_cost.h) than the constant one, so its cost is never higher.
// Points the cell cannot reach stay in the result, flagged and listed in the report; nothing is
// clipped. Throws InputError on bad parameters or path points; calls progress.checkCancel().
MotionResult solveMotion(const ArmIk& ik, const ControllerConvention& convention, const Trajectory& path,
                         const JointPathSetup& setup, const MotionParams& params, Progress& progress);

}  // namespace spira
