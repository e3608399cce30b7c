#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/path/trajectory.h"
#include "spira/prep/prep_params.h"

namespace spira {

// The sliding quintic through a trajectory (see quintic_path.h), sampled densely enough that the
// chords between samples stay within `params.resampleTolerance` of it and no sample gap exceeds
// `params.maxSpacing`. Every source point is a sample, so the decimation that follows can keep any of
// them and the source's own points are the ones it measures its tolerances at.
struct SmoothedSamples {
  Trajectory samples;               // the dense samples, channels kept (linear between source points)
  std::vector<double> sourceParam;  // per sample: k + u, parameter u in [0, 1) of source interval k
  double maxOffset = 0.0;           // mm: how far the smoothing moved a sample from the source polyline
};

SmoothedSamples smoothTrajectory(const Trajectory& source, const PrepParams& params, Progress& progress);

// Samples per interval for a chord error `tolerance` (mm) on a curve whose second derivative with
// respect to u peaks at `maxSecondDerivative`: the chord error of a span of length h in u is about
// |X''| h^2 / 8.
int samplesForChordError(double maxSecondDerivative, double tolerance);

}  // namespace spira
