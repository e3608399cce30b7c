#pragma once

#include <vector>

#include "spira/path/trajectory.h"
#include "spira/prep/quintic.h"

namespace spira {

// The sliding quintic through every point of a trajectory (002_4d923f9355c20a15.txt §I.2.1.1): on each
// interval k (points k -> k+1) one quintic Hermite per quantity - the position and the three frame
// vectors n, t, b - matching at both ends the first and second derivatives of the parabola through
// the point and its neighbours (chord-length parameter). The curve passes through every point and is
// C2 where the path is a single smooth run.
//
// Runs end (one-sided parabola rule, so the curve keeps a C0 corner there) at the path's ends, at a
// corner sharper than `cornerAngle`, and on both sides of a straight interval. An interval is straight
// - positions linear, frames slerped - when it has no length, when it changes the sub-path or switches
// the arc, or when `smooth` is false. Scalar channels are always linear in u: a quintic would
// overshoot a step of travel speed or wire feed. Point labels (path, revolution, generatrix, arcOn)
// come from the interval's first point. Holds a pointer to `source`, which must outlive it.
class QuinticPath {
 public:
  struct Curves {
    Quintic3 position, normal, tangent, build;
  };

  QuinticPath(const Trajectory& source, bool smooth, double cornerAngle);

  size_t intervals() const { return chord_.size(); }
  double chordLength(size_t k) const { return chord_[k]; }
  bool isStraight(size_t k) const { return straight_[k] != 0; }
  // The four quintics of a curved interval (meaningless for a straight one).
  Curves curves(size_t k) const;
  // The point at parameter u in [0, 1] of interval k: u = 0 gives source point k.
  TrajectoryPoint point(size_t k, double u) const;
  // Same, reusing the interval's curves (from curves(k)) when sweeping many u.
  TrajectoryPoint point(size_t k, double u, const Curves& c) const;
  // Extra channels at (k, u), in map order.
  void extraValues(size_t k, double u, std::vector<double>& out) const;

 private:
  // Derivatives (per chord length) of a vector quantity at point k, as the start (right side) or
  // the end (left side) of an interval.
  ParabolaDerivatives derivativesAt(size_t k, bool rightSide, Vec3 TrajectoryPoint::*member) const;
  bool interiorOfRun(size_t k) const { return runBreak_[k] == 0; }

  const Trajectory* source_;
  std::vector<double> chord_;
  std::vector<char> straight_;  // per interval
  std::vector<char> runBreak_;  // per point
};

}  // namespace spira
