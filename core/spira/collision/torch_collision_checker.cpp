#include "spira/collision/torch_collision_checker.h"

#include <algorithm>

#include "spira/collision/tilt_about_tangent.h"
#include "spira/path/tool_frame.h"

namespace spira {

namespace {

double resolvedWindow(const TorchParams& torch, const DepositParams& deposit)
{
  validateTorchParams(torch);
  return deposit.window < 0.0 ? torch.standoff + torch.nozzleRadius : deposit.window;
}

}  // namespace

TorchCollisionChecker::TorchCollisionChecker(const Trajectory& plan, const TorchParams& torch,
                                             const DepositParams& deposit, CollisionScene scene)
    : points_(plan.points),
      torch_(torch),
      deposit_(plan, deposit, resolvedWindow(torch, deposit)),
      scene_(std::move(scene))
{
}

TorchSolid TorchCollisionChecker::torchAt(size_t i, double tiltRad) const
{
  return TorchSolid(torch_, toolFrame(tiltAboutTangent(points_[i], tiltRad)));
}

unsigned TorchCollisionChecker::hits(size_t i, double tiltRad) const
{
  const TorchSolid solid = torchAt(i, tiltRad);
  unsigned found = scene_.hits(solid, torch_.clearance);
  if (deposit_.capsules().intersects(solid, torch_.clearance, deposit_.visibleEnd(i)))
    found |= kCollisionDeposit;
  return found;
}

bool TorchCollisionChecker::collides(size_t i, double tiltRad) const
{
  uint32_t none = CapsuleBvh::kAll;
  return collides(i, tiltRad, none);
}

bool TorchCollisionChecker::collides(size_t i, double tiltRad, uint32_t& depositHint) const
{
  const TorchSolid solid = torchAt(i, tiltRad);
  if (deposit_.capsules().intersects(solid, torch_.clearance, deposit_.visibleEnd(i), &depositHint))
    return true;
  return scene_.hits(solid, torch_.clearance) != 0;
}

double TorchCollisionChecker::clearance(size_t i, double tiltRad, double maxDistance, double slack) const
{
  const TorchSolid solid = torchAt(i, tiltRad);
  const double toDeposit =
      deposit_.capsules().nearest(solid, deposit_.visibleEnd(i), maxDistance, slack).distance;
  return scene_.clearance(solid, std::min(maxDistance, toDeposit), slack);
}

std::vector<size_t> TorchCollisionChecker::depositSegmentsHit(size_t i, double tiltRad) const
{
  const auto& caps = deposit_.capsules();
  const std::vector<size_t> indices =
      caps.within(torchAt(i, tiltRad), torch_.clearance, deposit_.visibleEnd(i));
  std::vector<size_t> segments;
  segments.reserve(indices.size());
  for (const size_t c : indices) segments.push_back(caps.key(c));
  std::sort(segments.begin(), segments.end());
  return segments;
}

}  // namespace spira
