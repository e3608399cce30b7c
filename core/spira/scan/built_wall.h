#pragma once

#include <cstdint>
#include <vector>

#include "spira/path/trajectory.h"
#include "spira/scan/point_cloud.h"

namespace spira {

// How the beads actually laid differ from the plan, for simulated builds: each bead's height is the
// planned one times (1 + error). Uniform: `relative` everywhere; sag: `relative` weighted by how much the
// point's surface normal faces `side` (zero on the far side), the one-sided slump of a wall. Either only
// on the points before `until` (a fraction of the plan's points, 0..1).
struct DepositErrors {
  enum class Kind { Uniform, Sag };
  Kind kind = Kind::Uniform;
  double relative = 0.0;  // -0.08: 8 % under-deposit
  double until = 1.0;
  Vec3 side = Vec3::UnitX();
  double relativeAt(const Trajectory& plan, size_t i) const;
};

// For each point before `at`: how far its bead's top lies below the planned one, along b (mm). The
// beads under a point on its generatrix (the same place in earlier revolutions) carry their shortfall
// up: each adds what it lacked, -relative * height.
std::vector<double> builtShortfall(const Trajectory& plan, size_t at, const DepositErrors& errors);

// For each point: the index of the point under it on its generatrix (the latest earlier point of the
// same sub-path with the same generatrix), or SIZE_MAX for the first revolution's.
std::vector<size_t> pointsBelow(const Trajectory& plan);

// A laser-line scan of the wall as built up to `at`: the crown of each bead (a half circle of the bead
// width across the wall) and both faces of the wall down `depth` mm, for the beads of the last
// `revolutions` revolutions on each generatrix, lowered by their shortfall, with gaussian noise of
// `noiseMm` along the surface. Repeatable for a seed.
PointCloud scanOfBuild(const Trajectory& plan, size_t at, const std::vector<double>& shortfall,
                       double beadWidth, int revolutions, double depth, double noiseMm,
                       std::uint64_t seed = 1);

// The wall's top as measured by a scan at the last bead laid on each generatrix before `at`. Each scan
// point over the bead (within a quarter of the bead width across it and half a step along it) tells
// where the crown's top is, the crown taken as a half circle of the bead width; the median of them is
// kept, so noise and stray points do not lift it.
struct MeasuredEdge {
  std::vector<size_t> points;     // the last bead on each generatrix, ascending
  std::vector<double> shortfall;  // how far below the planned top the measured one lies (mm, along b)
  std::vector<size_t> samples;    // scan points each was measured from (0: none, the shortfall interpolated)
  size_t unmeasured = 0;          // points the scan did not cover
};
MeasuredEdge measureTopEdge(const Trajectory& plan, size_t at, const PointCloud& scan, double beadWidth);

}  // namespace spira
