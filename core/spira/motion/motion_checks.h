#pragma once

#include <vector>

#include "spira/motion/motion_report.h"
#include "spira/path/joint_trajectory.h"
#include "spira/path/trajectory.h"

namespace spira {

// The per-point checks of a solved motion: fills the reachability lists, limit margins,
// dexterity, speed ratios (overall, per point, per axis) and cable twist fields of `report` (the
// rest is left alone).
// `reached[i]`: point i was reached (motion_report.h); the joint trajectory's limits (controller
// axes, and positioner axes when it has one) are the ones checked. `path` gives segment lengths
// and travel speeds. cableTwistLimitDeg 0 = no limit.
void checkMotion(const Trajectory& path, const JointTrajectory& joints, const std::vector<bool>& reached,
                 double cableTwistLimitDeg, MotionReport& report);

}  // namespace spira
