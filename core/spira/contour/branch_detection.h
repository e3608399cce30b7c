#pragma once

#include <vector>

#include "spira/contour/iso_contour.h"

namespace spira {

// Multi-branch detection (thesis 000_dbb97c2716e10cc3.txt §3.4.3): with a field grown from the base, a
// mono-branch part has one contour per level; where the count changes the part splits (or branches merge).
struct BranchChange {
  size_t levelIndex = 0;  // first level with the new count
  double value = 0.0;     // its field value
  size_t before = 0;      // contours at the previous level
  size_t after = 0;       // contours at this level
  double meanZ = 0.0;     // mean z of this level's contour points, mm: where on the part it happens
  bool splits() const { return after > before; }
};

// Contours per level.
std::vector<size_t> contourCounts(const std::vector<IsoLevel>& levels);

// Every change of the contour count from one level to the next, in level order.
std::vector<BranchChange> findBranchChanges(const std::vector<IsoLevel>& levels);

// Mean z of the points of all contours of a level (0 when it has none).
double meanZ(const IsoLevel& level);

}  // namespace spira
