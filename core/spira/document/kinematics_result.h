#pragma once

#include <vector>

#include "spira/path/joint_trajectory.h"
#include "spira/path/trajectory.h"

namespace spira {

// What the checks found at one point of a solved motion (index-aligned with the joints).
struct KinematicsCheck {
  bool reachable = true;
  double dexterity = 1.0;       // smallest/largest singular value ratio, 0 at a singularity
  double limitMarginDeg = 0.0;  // smallest distance of any axis to its limits, negative outside
  bool collision = false;       // torch against deposit/substrate, or a robot link, unresolved

  bool operator==(const KinematicsCheck& o) const;
  bool operator!=(const KinematicsCheck& o) const { return !(*this == o); }
};

// The kinematics stage of a plan: the robot (and positioner) motion solved on the document's
// cell, the per-point checks, the controller limits of every axis and the poses it was solved
// for (its report is the stage's, StageReports::kinematics). Immutable once made; the document holds
// it by shared pointer.
struct KinematicsResult {
  JointTrajectory joints;
  // The trajectory the joints were solved for (part frame): the plan with the torch tilts that
  // cleared collisions. Point i of `path` is point i of `joints`.
  Trajectory path;
  std::vector<KinematicsCheck> checks;  // one per point
  // Robot axes A1..A6 / J1..J6, then the positioner axes E1, E2 when the cell has one
  // (controller degrees, degrees per second).
  std::vector<AxisLimit> axes;

  size_t size() const { return joints.size(); }
  // Every point reachable and free of collisions.
  bool allReachable() const;
  size_t collisionCount() const;

  bool operator==(const KinematicsResult& o) const;
  bool operator!=(const KinematicsResult& o) const { return !(*this == o); }
};

// Axis values of point `i` in the order of `axes` (robot axes, then positioner axes).
std::vector<double> axisValuesDeg(const KinematicsResult& r, size_t i);

// Builds the result: fills `axes` from the joint trajectory's limits and the checks from its
// points (reachable, dexterity, collision) and the distance of every axis to its limits.
KinematicsResult makeKinematicsResult(JointTrajectory joints, Trajectory path);

}  // namespace spira
