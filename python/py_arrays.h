#pragma once

#include <pybind11/pybind11.h>

#include "py_plan.h"

namespace spira::python {

// Plan's per-point arrays of the planned path (the rows of trajectory.csv): positions, normals,
// tangents, build directions, revolution, generatrix, path, height, travel speed, wire feed, arc and
// the extra channels.
void bindTrajectoryArrays(pybind11::class_<PlannedPart>& plan);

// Plan's joints (N x 6), positioner axes, reachability and collisions (None without a cell), and the
// thermal stage's per-point arrays (None when it did not run).
void bindMotionArrays(pybind11::class_<PlannedPart>& plan);

}  // namespace spira::python
