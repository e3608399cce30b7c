#pragma once

#include <Eigen/Core>

namespace spira {

// Joint values of a 6-axis arm in the URDF convention (radians, joint 1 first). Controller
// conventions (degrees, couplings) are applied only at the edge, see controller_convention.h.
using JointVector = Eigen::Matrix<double, 6, 1>;

}  // namespace spira
