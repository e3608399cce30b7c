#pragma once

#include <map>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/path/trajectory.h"
#include "spira/prep/prep_params.h"

namespace spira {

// What the preparation did, measured on the result rather than taken from the algorithm's intent.
// Deviations compare every dense sample of the smoothed path (so every source point too) with the
// prepared path's motion model: straight segment, slerped frame, linear channels (see sample_set.h).
struct PrepReport {
  size_t pointsIn = 0;
  size_t samples = 0;  // dense samples on the smoothed path
  size_t pointsOut = 0;
  double maxChordDeviation = 0.0;                     // mm, sample to prepared segment
  double maxSmoothingOffset = 0.0;                    // mm, smoothed path to source polyline
  double maxOrientationDeviation = 0.0;               // rad
  std::map<std::string, double> maxChannelDeviation;  // by channel name, channel unit
  double minSegment = 0.0;      // mm, shortest prepared segment (0 when fewer than two points)
  double maxSegment = 0.0;      // mm, longest
  size_t spacingOverrides = 0;  // segments stretched to minSpacing beyond the tolerances
};

struct PreparedTrajectory {
  Trajectory trajectory;
  // Per output point: the source point it stands for (the nearer end of its source interval) and its
  // exact place on the source, k + u (interval k, parameter u in [0, 1)), so joint data and reports
  // can follow the points.
  std::vector<size_t> sourceIndex;
  std::vector<double> sourceParam;
  PrepReport report;
};

// Smoothing (A.2.1) then decimation (A.2.2) of a planned trajectory before export; see prep_params.h.
// Throws InputError for invalid parameters or channels.
PreparedTrajectory prepareTrajectory(const Trajectory& source, const PrepParams& params, Progress& progress);

}  // namespace spira
