#include "spira/collision/deposit_model.h"

#include <cmath>
#include <string>

#include "spira/base/error.h"
#include "spira/path/tool_tilt.h"

namespace spira {

DepositModel::DepositModel(const Trajectory& plan, const DepositParams& params, double windowLength)
    : window_(windowLength)
{
  if (!std::isfinite(params.beadWidth) || params.beadWidth <= 0.0)
    throw InputError("bead width " + std::to_string(params.beadWidth) + " mm for the deposit model",
                     "give the bead width in mm, above zero");
  if (!std::isfinite(windowLength) || windowLength < 0.0)
    throw InputError("deposit window " + std::to_string(windowLength) + " mm",
                     "give zero or more mm of fresh deposit to ignore behind the torch");
  const auto& pts = plan.points;
  const double radius = 0.5 * params.beadWidth;
  // The bead lies along the build direction, whichever way the torch leans (tool_tilt.h).
  const auto axisPoint = [&](size_t k) {
    return params.topAtPath ? Vec3(pts[k].position - radius * upDirection(plan, k).normalized())
                            : pts[k].position;
  };
  std::vector<Capsule> capsules;
  std::vector<uint32_t> keys;
  for (size_t k = 0; k + 1 < pts.size(); ++k) {
    if (!pts[k].arcOn) continue;
    capsules.push_back({axisPoint(k), axisPoint(k + 1), radius});
    keys.push_back(static_cast<uint32_t>(k));
  }
  capsules_ = CapsuleBvh(std::move(capsules), std::move(keys));

  arcLength_.assign(pts.size(), 0.0);
  for (size_t i = 1; i < pts.size(); ++i)
    arcLength_[i] = arcLength_[i - 1] + (pts[i].position - pts[i - 1].position).norm();
  visibleEnd_.assign(pts.size(), 0);
  size_t end = 0;  // segments [0, end) are visible; grows with i since arc length does
  for (size_t i = 0; i < pts.size(); ++i) {
    while (end + 1 <= i && arcLength_[end + 1] <= arcLength_[i] - window_) ++end;
    visibleEnd_[i] = static_cast<uint32_t>(end);
  }
}

}  // namespace spira
