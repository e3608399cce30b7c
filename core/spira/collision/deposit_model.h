#pragma once

#include <cstdint>
#include <vector>

#include "spira/collision/capsule_bvh.h"
#include "spira/path/trajectory.h"

namespace spira {

// How the material already laid is modelled for torch collision checks.
struct DepositParams {
  double beadWidth = 4.0;  // mm; each path segment becomes a capsule of radius beadWidth / 2
  // Sink the capsule axis by its radius along -b so the bead's top passes through the path point
  // (path points sit on the top of the bead being laid). Off: the capsule is centred on the path.
  bool topAtPath = true;
  // Fresh deposit ignored behind the current point, as arc length along the path in mm (the sliding
  // window, see DepositModel). Negative: the torch standoff plus its nozzle radius.
  double window = -1.0;
};

// The deposit as one capsule per path segment (segment k joins points k and k+1 and exists when
// point k has the arc on), in one static hierarchy keyed by segment index.
//
// The sliding-window rule: the torch at point i is checked against segments k that were finished
// before it (k + 1 <= i) and end at least `window` mm of arc length behind it: s(k+1) <= s(i) - window.
// The bead right behind the arc touches the wire and the weld pool by design; with the default
// window (standoff + nozzle radius) every ignored segment lies within that distance of the TCP along
// the path, i.e. under the arc and the nozzle, where contact is the process and not a collision.
// Material laid earlier, however close in space (the previous layer, a neighbouring wall), counts.
// The deposit grows without a rebuild: a query for point i passes keyEnd = visibleEnd(i).
class DepositModel {
 public:
  DepositModel(const Trajectory& plan, const DepositParams& params, double windowLength);

  // Segments with key < visibleEnd(i) are the deposit the torch at point i must avoid.
  uint32_t visibleEnd(size_t i) const { return visibleEnd_[i]; }
  const CapsuleBvh& capsules() const { return capsules_; }
  double windowLength() const { return window_; }
  double arcLength(size_t i) const { return arcLength_[i]; }

 private:
  CapsuleBvh capsules_;
  std::vector<double> arcLength_;
  std::vector<uint32_t> visibleEnd_;
  double window_ = 0.0;
};

}  // namespace spira
