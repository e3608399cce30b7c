#pragma once

#include "spira/path/spiral_report.h"
#include "spira/path/trajectory.h"

namespace spira {

// The phase a revolution belongs to, from the revolution counts in `report`.
SpiralPhase phaseOfRevolution(int revolution, const SpiralReport& report);

// Thesis Eq. 3.15, corrected to h_min <= h <= h_max, on the height channel of `path`: lists every
// point beyond [h_min - tol, h_max + tol] (tol = tolerance * h, in mm), fills the modulated-phase
// height statistics and sets `feasible` (see SpiralReport). Reads the revolution counts and
// lengthCriterion from `report`; `closurePointLast` marks the final point as the closure point.
void checkFeasibility(const Trajectory& path, double h, double hMin, double hMax, double tolerance,
                      bool closurePointLast, SpiralReport& report);

}  // namespace spira
