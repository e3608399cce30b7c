#pragma once

#include <vector>

#include "base_ring.h"
#include "generatrix_solver.h"

namespace spira::geodesic {

// What one spiral can lay: the thinnest and thickest deposit and the tolerance on both (mm).
struct LayerWindow {
  double hMin = 0.0;
  double hMax = 0.0;
  double tolerance = 0.0;
  bool known() const { return hMin > tolerance && hMax > hMin; }
  // The largest ratio of two generatrix lengths one spiral can lay (thesis Eq. 3.6: with
  // n = min(G) / h_min layers, (max(G) - min(G)) / n <= h_max - h_min is max(G) / min(G) <= h_max / h_min).
  double lengthRatio() const { return (hMax + tolerance) / (hMin - tolerance); }
};

// Bounds on the exact geodesic length from a base point to the target, known before any exact
// search: no surface path is shorter than the straight segment to the nearest target point, and
// the shortest path along mesh edges (entered straight across the base point's face) is a
// surface path, so no geodesic is longer.
struct LengthBounds {
  double lower = 0.0;
  double upper = 0.0;
};
std::vector<LengthBounds> boundGeneratrixLengths(const GeodesicMesh& mesh,
                                                 const std::vector<BasePoint>& bases,
                                                 const GeodesicTarget& target);

// Throws InputError, naming the two base points and the window, when the generatrices cannot be
// laid by one spiral in `window`: the longest is certainly more than lengthRatio() times the
// shortest (the largest lower bound over the smallest upper bound). Exact lengths pass as equal
// bounds. Does nothing for an unknown window.
void requireLengthsFitWindow(const std::vector<LengthBounds>& lengths, const std::vector<BasePoint>& bases,
                             const LayerWindow& window, bool open);

}  // namespace spira::geodesic
