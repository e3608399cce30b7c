#include "spira/prep/sample_set.h"

#include <algorithm>
#include <cmath>

#include "spira/prep/channels.h"
#include "spira/prep/frame_math.h"

namespace spira {

SampleSet::SampleSet(const SmoothedSamples& smoothed, const Trajectory& source, const PrepParams& params)
    : chordTolerance_(params.chordTolerance), orientationTolerance_(params.orientationTolerance)
{
  const auto& pts = smoothed.samples.points;
  const size_t n = pts.size();
  std::vector<double> sourceArc(source.size(), 0.0);
  for (size_t k = 1; k < source.size(); ++k)
    sourceArc[k] = sourceArc[k - 1] + (source.points[k].position - source.points[k - 1].position).norm();

  position_.resize(n);
  frame_.resize(n);
  arc_.resize(n);
  sigma_.resize(n);
  protected_.assign(n, 0);
  for (size_t j = 0; j < n; ++j) {
    position_[j] = pts[j].position;
    frame_[j] = frameQuaternion(pts[j]);
    arc_[j] = j == 0 ? 0.0 : arc_[j - 1] + (position_[j] - position_[j - 1]).norm();
    const double param = smoothed.sourceParam[j];
    const size_t k = std::min(static_cast<size_t>(param), source.size() - 1);
    sigma_[j] =
        k + 1 < source.size() ? sourceArc[k] + (param - k) * (sourceArc[k + 1] - sourceArc[k]) : sourceArc[k];
    if (j > 0 && (pts[j].arcOn != pts[j - 1].arcOn || pts[j].path != pts[j - 1].path))
      protected_[j] = protected_[j - 1] = 1;
    if (j > 0 && params.keepRevolutionStarts && pts[j].revolution != pts[j - 1].revolution) protected_[j] = 1;
  }
  if (n > 0) protected_.front() = protected_.back() = 1;

  names_ = scalarChannelNames(smoothed.samples);
  for (const std::string& name : names_) {
    channel_.push_back(channelValues(smoothed.samples, name));
    double tol = params.extraTolerance;
    if (name == kHeightChannel)
      tol = params.heightTolerance;
    else if (name == kTravelSpeedChannel)
      tol = params.travelSpeedTolerance;
    else if (name == kWireFeedChannel)
      tol = params.wireFeedTolerance;
    else if (auto it = params.extraTolerances.find(name); it != params.extraTolerances.end())
      tol = it->second;
    tolerance_.push_back(tol);
  }
}

double SampleSet::fraction(size_t i, size_t a, size_t j) const
{
  const double span = sigma_[a] - sigma_[i];
  return span > 0.0 ? (sigma_[j] - sigma_[i]) / span : 0.0;
}

double SampleSet::chordDistance(size_t i, size_t a, size_t j) const
{
  const Vec3 ab = position_[a] - position_[i];
  const Vec3 aj = position_[j] - position_[i];
  const double len2 = ab.squaredNorm();
  const double f = len2 > 0.0 ? std::clamp(aj.dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (aj - f * ab).norm();
}

double SampleSet::angleTo(size_t i, size_t a, size_t j, double f) const
{
  return frame_[i].slerp(f, frame_[a]).angularDistance(frame_[j]);
}

bool SampleSet::fits(size_t i, size_t a) const
{
  for (size_t j = i + 1; j < a; ++j) {
    if (chordDistance(i, a, j) > chordTolerance_) return false;
    const double f = fraction(i, a, j);
    for (size_t c = 0; c < channel_.size(); ++c) {
      const std::vector<double>& v = channel_[c];
      if (std::abs(v[j] - (v[i] + f * (v[a] - v[i]))) > tolerance_[c]) return false;
    }
    if (angleTo(i, a, j, f) > orientationTolerance_) return false;
  }
  return true;
}

void SampleSet::deviation(size_t i, size_t a, size_t j, Deviation& out) const
{
  const double f = fraction(i, a, j);
  out.chord = chordDistance(i, a, j);
  out.angle = angleTo(i, a, j, f);
  out.channel.resize(channel_.size());
  for (size_t c = 0; c < channel_.size(); ++c) {
    const std::vector<double>& v = channel_[c];
    out.channel[c] = std::abs(v[j] - (v[i] + f * (v[a] - v[i])));
  }
}

}  // namespace spira
