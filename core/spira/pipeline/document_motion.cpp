#include "spira/pipeline/document_motion.h"

#include <chrono>
#include <cstdio>

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/pipeline/plan_motion.h"
#include "spira/pipeline/substrate_frame.h"
#include "spira/planning/placement_frame.h"
#include "spira/planning/plan_schemas.h"
#include "spira/robotcell/robot_cell.h"

namespace spira {

DocumentMotion solveDocumentMotion(const DocumentState& snapshot, const Trajectory& plan, double substrateZ,
                                   Progress& progress, bool resolveCollisions)
{
  DocumentMotion out;
  if (!snapshot.cell || plan.empty()) return out;
  const auto start = std::chrono::steady_clock::now();
  try {
    const RobotCell cell(*snapshot.cell);
    if (!cell.canSolve()) {
      out.warnings.push_back("Kinematics skipped: " + cell.ikRefusal() +
                             ". Choose a cell with a 6-axis arm.");
      return out;
    }
    MotionSettings settings = motionSettingsFrom(readPlanSections(snapshot.settings->params));
    settings.substrateZ = substrateZ;
    if (snapshot.substrate && snapshot.part)
      settings.substrate = substrateInBuildFrame(*snapshot.substrate, snapshot.part->T_world_part);
    settings.resolveCollisions = resolveCollisions;
    settings.part = snapshot.part ? snapshot.part->mesh.get() : nullptr;
    // A tilted part was planned with the world's up: the cell holds it the same way, so the
    // motion is solved in the build frame (where the substrate is a z plane) and turned back.
    const PlacementFrame frame(snapshot.part ? snapshot.part->T_world_part : Transform::Identity());
    Trajectory buildPlan;
    TriangleMesh buildMesh;
    if (!frame.identity()) {
      buildPlan = plan;
      frame.toBuild(buildPlan);
      if (settings.part) {
        buildMesh = frame.toBuild(*settings.part);
        settings.part = &buildMesh;
      }
    }
    PlanMotion motion = solvePlanMotion(cell, frame.identity() ? plan : buildPlan, settings, progress);
    if (!frame.identity()) frame.toPart(motion.trajectory);
    const MotionStageReport& report = motion.report;
    auto result = std::make_shared<const KinematicsResult>(
        makeKinematicsResult(std::move(motion.joints), std::move(motion.trajectory)));
    const auto unreachable = report.unreachablePoints;
    if (unreachable > 0)
      out.warnings.push_back("The robot cannot reach " + std::to_string(unreachable) + " of " +
                             std::to_string(result->size()) +
                             " points (shown in red). Move the part closer to the robot or change the cell.");
    if (!report.withinCableTwistLimit)
      out.warnings.push_back(
          "The torch cable twists beyond the cell's limit; enable the spin optimisation or "
          "change the part's placement.");
    if (!motion.withinJointSpeeds) {
      const JointSpeedRecord& speed = report.jointSpeed;
      if (speed.allowSlowdown)
        out.warnings.push_back(
            "Where the axes cannot keep up with the travel speed the controller slows down, "
            "and the deposit thickens beyond the window at " +
            std::to_string(motion.slowdown.outsideWindow) + " point(s).");
      else
        out.warnings.push_back("Axis " + speed.axis +
                               " would pass its speed limit at the planned travel speed. Let the controller "
                               "slow down (Process, Limits) or plan a slower process.");
    }
    if (motion.unresolvedCollisions > 0)
      out.warnings.push_back("The torch collides at " + std::to_string(motion.unresolvedCollisions) +
                             " point(s) that tilting could not clear (marked in red).");
    if (motion.robotCollisions > 0)
      out.warnings.push_back("A robot link hits the part, table or positioner at " +
                             std::to_string(motion.robotCollisions) + " checked point(s).");
    for (const std::string& w : report.cellWarnings) out.warnings.push_back(w);
    out.ok = motion.ok();
    out.report = std::make_shared<const MotionStageReport>(std::move(motion.report));
    out.result = std::move(result);
  } catch (const Cancelled&) {
    throw;
  } catch (const Error& e) {
    out.warnings.push_back(std::string("Kinematics failed: ") + e.what() +
                           (e.hint().empty() ? std::string() : " " + e.hint()));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace spira
