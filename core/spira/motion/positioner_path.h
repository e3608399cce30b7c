#pragma once

#include <array>
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
  // Whole turns added to each axis so that its range over the path fits its limits (windToFit).
  std::array<int, 2> turns{};
};

// Turns every point's build direction to within params.buildTiltToleranceDeg of the positioner's
// vertical (TiltRotatePositioner::solveWithin). The rotation aims at a smooth target: the previous
// point's rotation, less the point's turn about the rotation axis when params.turntableFollowsPoint
// (the table turns the part under the torch), and is moved off it only as far as the tolerance
// demands; the tilt then brings the build direction as close to the vertical as it can. Then the
// axes are wound to fit their limits (windToFit, params.limitMarginDeg). Needs setup.positioner.
PositionerPath placeOnPositioner(const Trajectory& path, const JointPathSetup& setup,
                                 const MotionParams& params, Progress& progress);

// Adds the same whole number of turns to axis k of every point, for each axis whose limits allow
// it, so that the axis's range over the `reached` points fits inside [lower + margin, upper -
// margin] of `chain`; the fewest turns that do (none when it already fits), since turning the
// axis a whole turn does not move the table. Without a margin if only that fits; a range that
// fits in no winding is centred between the limits. Returns the turns added per axis.
std::array<int, 2> windToFit(std::vector<Eigen::Vector2d>& axes, const std::vector<bool>& reached,
                             const KinematicChain& chain, double marginRad);

}  // namespace spira
