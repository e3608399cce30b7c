#include "spira/prep/prepare_trajectory.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spira/base/error.h"
#include "spira/prep/decimation.h"
#include "spira/prep/sample_set.h"
#include "spira/prep/smoothing.h"

namespace spira {

namespace {

void checkTolerances(const PrepParams& p)
{
  const auto nonNegative = [](double v) { return v >= 0.0; };
  bool ok = nonNegative(p.chordTolerance) && nonNegative(p.heightTolerance) &&
            nonNegative(p.travelSpeedTolerance) && nonNegative(p.wireFeedTolerance) &&
            nonNegative(p.orientationTolerance) && nonNegative(p.extraTolerance);
  for (const auto& [name, tol] : p.extraTolerances) ok = ok && nonNegative(tol);
  if (!ok) {
    throw InputError("a path-preparation tolerance is negative or not a number",
                     "set every chord, channel and orientation tolerance to zero or more");
  }
  if (!(p.minSpacing >= 0.0) || !(p.minSpacing < p.maxSpacing)) {
    throw InputError("the minimum point spacing must lie in [0, maximum spacing)",
                     "lower min_spacing below max_spacing (for example 0.5 mm and 5 mm)");
  }
}

PrepReport measure(const SampleSet& set, const std::vector<size_t>& kept, const Trajectory& out)
{
  PrepReport r;
  for (size_t c = 0; c < set.channelCount(); ++c) r.maxChannelDeviation[set.channelName(c)] = 0.0;
  SampleSet::Deviation d;
  std::vector<double> channelMax(set.channelCount(), 0.0);
  for (size_t m = 0; m + 1 < kept.size(); ++m) {
    for (size_t j = kept[m] + 1; j < kept[m + 1]; ++j) {
      set.deviation(kept[m], kept[m + 1], j, d);
      r.maxChordDeviation = std::max(r.maxChordDeviation, d.chord);
      r.maxOrientationDeviation = std::max(r.maxOrientationDeviation, d.angle);
      for (size_t c = 0; c < d.channel.size(); ++c) channelMax[c] = std::max(channelMax[c], d.channel[c]);
    }
  }
  for (size_t c = 0; c < set.channelCount(); ++c) r.maxChannelDeviation[set.channelName(c)] = channelMax[c];
  if (out.size() >= 2) {
    r.minSegment = std::numeric_limits<double>::infinity();
    for (size_t m = 1; m < out.size(); ++m) {
      const double len = (out.points[m].position - out.points[m - 1].position).norm();
      r.minSegment = std::min(r.minSegment, len);
      r.maxSegment = std::max(r.maxSegment, len);
    }
  }
  return r;
}

}  // namespace

PreparedTrajectory prepareTrajectory(const Trajectory& source, const PrepParams& params, Progress& progress)
{
  checkTolerances(params);
  SubProgress smoothProgress(progress, 0.0, 0.6, "smoothing");
  const SmoothedSamples smoothed = smoothTrajectory(source, params, smoothProgress);
  const SampleSet set(smoothed, source, params);
  SubProgress decimateProgress(progress, 0.6, 1.0, "decimating");
  const Selection selection = selectSamples(set, params, decimateProgress);

  PreparedTrajectory result;
  Trajectory& out = result.trajectory;
  out.points.reserve(selection.kept.size());
  for (auto& [name, values] : smoothed.samples.extra) out.extra[name].reserve(selection.kept.size());
  for (size_t j : selection.kept) {
    out.points.push_back(smoothed.samples.points[j]);
    for (const auto& [name, values] : smoothed.samples.extra) out.extra[name].push_back(values[j]);
    const double param = smoothed.sourceParam[j];
    result.sourceParam.push_back(param);
    result.sourceIndex.push_back(static_cast<size_t>(std::floor(param + 0.5)));
  }
  result.report = measure(set, selection.kept, out);
  result.report.pointsIn = source.size();
  result.report.samples = set.size();
  result.report.pointsOut = out.size();
  result.report.maxSmoothingOffset = smoothed.maxOffset;
  result.report.spacingOverrides = selection.spacingOverrides;
  progress.report(1.0, "path prepared");
  return result;
}

}  // namespace spira
