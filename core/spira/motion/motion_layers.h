#pragma once

#include <vector>

#include "spira/motion/motion_params.h"
#include "spira/path/trajectory.h"

namespace spira {

// One layer of the spin optimisation: a run of consecutive path points with the same sub-path
// and revolution index, with the abscissa x of its spin polynomial at each point.
struct MotionLayer {
  size_t first = 0;  // index of its first point in the path
  size_t count = 0;
  int path = 0;
  int revolution = 0;
  std::vector<double> x;  // count values, x[0] = 0
  bool hasNext = false;   // a next layer follows; its first point continues this polynomial
  double xNext = 1.0;     // x at the next layer's first point
};

// Splits the path into layers (params.variable picks x). Every point belongs to exactly one.
std::vector<MotionLayer> splitLayers(const Trajectory& path, const MotionParams& params);

}  // namespace spira
