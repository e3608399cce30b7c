#pragma once

#include <vector>

#include "spira/collision/collision_kind.h"
#include "spira/collision/collision_scene.h"
#include "spira/collision/deposit_model.h"
#include "spira/collision/torch_params.h"
#include "spira/collision/torch_solid.h"

namespace spira {

// Checks the torch at any point of a plan, optionally tilted about the travel direction, against
// the deposit laid before that point (sliding window, see DepositModel), the substrate and the
// obstacles. Builds its hierarchies once; every query is const and thread-safe, so callers may run
// points in parallel. "Collision" means nearer than TorchParams::clearance.
class TorchCollisionChecker {
 public:
  TorchCollisionChecker(const Trajectory& plan, const TorchParams& torch, const DepositParams& deposit = {},
                        CollisionScene scene = {});

  size_t size() const { return points_.size(); }
  const TrajectoryPoint& point(size_t i) const { return points_[i]; }
  const TorchParams& torch() const { return torch_; }
  const DepositModel& deposit() const { return deposit_; }
  const CollisionScene& scene() const { return scene_; }

  // The torch at point i turned by tiltRad about t (tiltAboutTangent), placed by toolFrame().
  TorchSolid torchAt(size_t i, double tiltRad = 0.0) const;
  // CollisionKind bits of everything the torch at point i comes within the clearance of.
  unsigned hits(size_t i, double tiltRad = 0.0) const;
  // Same answer as hits() != 0, stopping at the first hit.
  bool collides(size_t i, double tiltRad = 0.0) const;
  // The same, for a series of queries at one point (a tilt search): `depositHint` starts at
  // CapsuleBvh::kAll and carries the deposit segment last hit to the next query, which tries it
  // first. Same answers, a fraction of the cost while the torch still collides.
  bool collides(size_t i, double tiltRad, uint32_t& depositHint) const;
  // Distance from the torch to the nearest deposit, substrate or obstacle, capped at maxDistance
  // (0 when touching or overlapping), accurate to `slack` mm (an exact answer, slack 0, costs several
  // times more: the nozzle sits over many nearly equidistant beads).
  double clearance(size_t i, double tiltRad = 0.0, double maxDistance = 100.0, double slack = 1e-3) const;
  // The deposit segments (path segment indices, sorted) within the clearance of the torch.
  std::vector<size_t> depositSegmentsHit(size_t i, double tiltRad = 0.0) const;

 private:
  std::vector<TrajectoryPoint> points_;
  TorchParams torch_;
  DepositModel deposit_;
  CollisionScene scene_;
};

}  // namespace spira
