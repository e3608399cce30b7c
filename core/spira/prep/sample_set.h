#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "spira/path/trajectory.h"
#include "spira/prep/prep_params.h"
#include "spira/prep/smoothing.h"

namespace spira {

// The dense samples flattened for the decimation's inner loop, with the motion model the robot
// program will follow between two kept samples i < a: a straight TCP segment, the tool frame slerped,
// every scalar channel ramped linearly. Frames and channels are interpolated by the fraction
// f = (sigma_j - sigma_i) / (sigma_a - sigma_i) of the source arc position sigma (the source
// polyline's arc length, linear in u inside a source interval), which is also how a report maps a
// source point onto the prepared path.
class SampleSet {
 public:
  SampleSet(const SmoothedSamples& smoothed, const Trajectory& source, const PrepParams& params);

  size_t size() const { return position_.size(); }
  size_t channelCount() const { return names_.size(); }
  const std::string& channelName(size_t c) const { return names_[c]; }
  double arc(size_t j) const { return arc_[j]; }      // arc length along the samples, mm
  double sigma(size_t j) const { return sigma_[j]; }  // source arc position, mm
  // Samples every output must keep: the ends, both sides of an arc switch or sub-path change, and
  // revolution starts when asked.
  bool isProtected(size_t j) const { return protected_[j] != 0; }

  // True when every sample strictly between i and a is within all tolerances of the segment i -> a.
  bool fits(size_t i, size_t a) const;

  struct Deviation {
    double chord = 0.0;           // mm, distance to the straight segment
    double angle = 0.0;           // rad, to the slerped frame
    std::vector<double> channel;  // absolute, per channel, channel units
  };
  // The deviation of sample j (i <= j <= a) from the segment i -> a.
  void deviation(size_t i, size_t a, size_t j, Deviation& out) const;

 private:
  double fraction(size_t i, size_t a, size_t j) const;
  double chordDistance(size_t i, size_t a, size_t j) const;
  double angleTo(size_t i, size_t a, size_t j, double f) const;

  std::vector<Vec3> position_;
  std::vector<Eigen::Quaterniond> frame_;
  std::vector<double> arc_, sigma_;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> channel_;  // [channel][sample]
  std::vector<double> tolerance_;             // per channel
  std::vector<char> protected_;
  double chordTolerance_, orientationTolerance_;
};

}  // namespace spira
