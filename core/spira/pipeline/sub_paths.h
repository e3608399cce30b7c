#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/motion/motion_solver.h"
#include "spira/path/trajectory.h"
#include "spira/robotcell/robot_cell.h"

namespace spira {

// A run of consecutive points with one `path` index: one sub-path of a multi-branch plan (a
// single spiral is one run). [begin, end) into the trajectory.
struct SubPathRange {
  int path = 0;
  size_t begin = 0;
  size_t end = 0;
  size_t size() const { return end - begin; }
};

// The runs of `t` in order; empty for an empty trajectory.
std::vector<SubPathRange> subPathRanges(const Trajectory& t);

// Points [range.begin, range.end) of `t` with their extra channels.
Trajectory subTrajectory(const Trajectory& t, const SubPathRange& range);

// Appends `part` (points and extra channels) to `whole`; extra channels missing on one side are
// filled with zeros so every channel keeps the trajectory's size.
void appendTrajectory(Trajectory& whole, const Trajectory& part);

// The motion of a plan with one or more sub-paths: every sub-path is solved on its own (its own
// seed and arm configuration, chosen at its first point, held inside it; it may change between
// sub-paths, where the program moves the arm with a joint move), and the results are laid one
// after the other, index-aligned with `path`. The report merges the sub-paths' reports (indices
// into the whole path, extrema over all); `setups` receives the setup of each sub-path.
MotionResult solveSubPaths(const RobotCell& cell, const Trajectory& path, const MotionParams& params,
                           Progress& progress, std::vector<JointPathSetup>* setups = nullptr);

}  // namespace spira
