#include "spira/prep/smoothing.h"
#include "spira/base/segment_distance.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"
#include "spira/prep/channels.h"
#include "spira/prep/frame_math.h"
#include "spira/prep/quintic_path.h"

namespace spira {

namespace {

// Guards against a pathological interval turning into millions of samples.
constexpr int kMaxSamplesPerInterval = 100000;

void checkParams(const PrepParams& params)
{
  if (!(params.resampleTolerance > 0.0)) {
    throw InputError("the smoothing resample tolerance must be positive",
                     "set resample_tolerance to a small length such as 0.01 mm");
  }
  if (!(params.maxSpacing > 0.0) || !std::isfinite(params.maxSpacing)) {
    throw InputError("the maximum point spacing must be a positive finite length",
                     "set max_spacing to a few millimetres (about 5 mm keeps a robot's form error low)");
  }
}

}  // namespace

int samplesForChordError(double maxSecondDerivative, double tolerance)
{
  const double m = std::ceil(std::sqrt(std::max(0.0, maxSecondDerivative) / (8.0 * tolerance)));
  return static_cast<int>(std::clamp(m, 1.0, static_cast<double>(kMaxSamplesPerInterval)));
}

SmoothedSamples smoothTrajectory(const Trajectory& source, const PrepParams& params, Progress& progress)
{
  checkParams(params);
  checkExtraChannels(source);
  SmoothedSamples out;
  out.samples.extra = source.extra;
  for (auto& [name, values] : out.samples.extra) values.clear();
  const size_t n = source.size();
  if (n == 0) return out;

  const QuinticPath path(source, params.smooth, params.cornerAngle);
  out.samples.points.reserve(n + n / 4);
  out.sourceParam.reserve(n + n / 4);
  std::vector<double> extras;
  const auto emit = [&](size_t k, double u, const TrajectoryPoint& p) {
    out.samples.points.push_back(p);
    out.sourceParam.push_back(static_cast<double>(k) + u);
    if (out.samples.extra.empty()) return;
    path.extraValues(k, u, extras);
    size_t e = 0;
    for (auto& [name, values] : out.samples.extra) values.push_back(extras[e++]);
  };

  for (size_t k = 0; k < path.intervals(); ++k) {
    if ((k & 4095) == 0) {
      progress.checkCancel();
      progress.report(static_cast<double>(k) / static_cast<double>(path.intervals()), "smoothing");
    }
    const TrajectoryPoint& a = source.points[k];
    const TrajectoryPoint& b = source.points[k + 1];
    int m = 1;
    QuinticPath::Curves c;
    if (path.isStraight(k)) {
      m = static_cast<int>(std::ceil(path.chordLength(k) / params.maxSpacing));
    } else {
      c = path.curves(k);
      double peak = 0.0, arc = 0.0;
      Vec3 prev = a.position;
      for (int j = 0; j <= 4; ++j) {
        peak = std::max(peak, c.position.secondDerivative(0.25 * j).norm());
        if (j > 0) {
          const Vec3 q = c.position.value(0.25 * j);
          arc += (q - prev).norm();
          prev = q;
        }
      }
      // 1 % margin: the four-chord arc estimate is a little short of the quintic's length.
      m = std::max(samplesForChordError(peak, params.resampleTolerance),
                   static_cast<int>(std::ceil(1.01 * arc / params.maxSpacing)));
    }
    m = std::clamp(m, 1, kMaxSamplesPerInterval);
    emit(k, 0.0, path.point(k, 0.0, c));
    for (int j = 1; j < m; ++j) {
      const double u = static_cast<double>(j) / m;
      const TrajectoryPoint p = path.point(k, u, c);
      out.maxOffset = std::max(out.maxOffset, pointSegmentDistance(p.position, a.position, b.position));
      emit(k, u, p);
    }
  }
  if (n >= 2) {
    emit(n - 2, 1.0, path.point(n - 2, 1.0));
  } else {
    TrajectoryPoint only = source.points.front();
    orthonormaliseFrame(only);
    out.samples.points.push_back(only);
    out.sourceParam.push_back(0.0);
    for (auto& [name, values] : out.samples.extra) values.push_back(source.extra.at(name).front());
  }
  return out;
}

}  // namespace spira
