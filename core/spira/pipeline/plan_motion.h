#pragma once

#include <memory>

#include "spira/base/progress.h"
#include "spira/document/stage_reports.h"
#include "spira/mesh/substrate_surface.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/motion/motion_params.h"
#include "spira/motion/slowdown_deposit.h"
#include "spira/path/joint_trajectory.h"
#include "spira/path/process_model.h"
#include "spira/path/trajectory.h"
#include "spira/planning/plan_schemas.h"
#include "spira/plugin/parameter.h"
#include "spira/robotcell/robot_cell.h"

namespace spira {

struct MotionSettings {
  double beadWidth = 5.2;   // mm: the deposit tube the torch must clear
  double substrateZ = 0.0;  // mm, part frame: the substrate plane (normal +Z)
  // A substrate mesh (part frame) in place of the plane, for the torch's and the arm's collisions; nullptr:
  // the plane.
  std::shared_ptr<const SubstrateSurface> substrate;
  // Tilt the torch about the travel direction where it would hit the deposit or the substrate
  // (the source's resolution); off: collisions are only reported.
  bool resolveCollisions = true;
  // The part's mesh (its own frame): with it, the robot's links are checked against the part, the
  // plate under it and the positioner every `linkCheckSpacing` mm of path (and at both ends).
  const TriangleMesh* part = nullptr;
  double linkCheckSpacing = 10.0;
  // Layer-wise optimisation of the torch spin (Chalvin ch. 4); off: the spin is held constant in
  // the robot's base frame. The cable-twist limit is the cell's.
  bool optimiseSpin = true;
  // The process the plan was made with: process.allowSlowdown lets the controller slow down where
  // an axis would pass its speed limit at the planned travel speed, and its height model says how
  // much the deposit thickens there (slowdown_deposit.h), which must stay inside `window`.
  ProcessSettings process;
  DepositWindow window;
};

// The motion parameters of a cell and these settings.
MotionParams motionParamsFor(const RobotCell& cell, const MotionSettings& settings);

// Settings from the plan's spiral and process sections: bead width, process (allow_slowdown and
// the height model) and the deposit window; the rest at their defaults.
MotionSettings motionSettingsFrom(const PlanSections& sections);

// The robot side of a plan: the torch checked (and, when allowed, tilted) against the deposit so
// far and the substrate, then every point solved on the cell.
struct PlanMotion {
  Trajectory trajectory;  // the plan, with torch tilts where collisions were resolved
  JointTrajectory joints;
  bool reachable = false;           // every point reached within the controller limits
  size_t unresolvedCollisions = 0;  // torch against deposit and substrate
  size_t robotCollisions = 0;       // checked points where a robot link hits something
  // Every axis keeps within its speed limit at the planned travel speed, or the controller may
  // slow down (settings.process.allowSlowdown) and the thicker deposit still fits the window.
  bool withinJointSpeeds = true;
  SlowdownReport slowdown;  // the points slowed down (filled when slowing down is allowed)
  MotionStageReport report;
  bool ok() const
  {
    return reachable && unresolvedCollisions == 0 && robotCollisions == 0 && withinJointSpeeds;
  }
};

PlanMotion solvePlanMotion(const RobotCell& cell, const Trajectory& plan, const MotionSettings& settings,
                           Progress& progress);

}  // namespace spira
