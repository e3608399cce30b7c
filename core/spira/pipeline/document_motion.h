#pragma once

#include <memory>
#include <string>
#include <vector>

#include "spira/document/document_state.h"

namespace spira {

class Progress;

// What the kinematics stage of a document's plan hands back (no Document is touched: worker threads run it).
struct DocumentMotion {
  std::shared_ptr<const KinematicsResult> result;  // null: no cell, or the stage failed
  std::shared_ptr<const MotionStageReport> report;
  std::vector<std::string> warnings;  // unreachable points, collisions, missing meshes, failures
  // Every point reached and free of collisions, every axis within its speed limit.
  bool ok = false;
  double seconds = 0.0;  // wall time of the stage (0 without a cell)
};

// Solves the robot (and positioner) motion of `plan` (part frame, with process channels) on the
// cell of `snapshot`: torch collisions against the deposit and substrate, IK of every point,
// robot links against the part. A cell that cannot be read or solved is a warning, not an error:
// the plan itself stays valid. Cancellation propagates (Cancelled). `resolveCollisions` false keeps
// the torch's planned tilt where it collides (the collisions are reported).
DocumentMotion solveDocumentMotion(const DocumentState& snapshot, const Trajectory& plan, double substrateZ,
                                   Progress& progress, bool resolveCollisions = true);

}  // namespace spira
