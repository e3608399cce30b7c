#pragma once

#include <vector>

#include "spira/thermal/thermal_solver.h"

namespace spira {

// Snapshots of the temperature field over the build, for playback and ParaView: one frame every
// `interval` seconds of simulated time (the first step at or past each multiple), plus the last.
// Single precision: a frame is for looking at, and the dome's 16,500 nodes x 200 frames stay 13 MB.
struct ThermalFrames {
  std::vector<double> times;               // s
  std::vector<std::vector<float>> values;  // [frame][node], C; NaN where not yet deposited
  bool empty() const { return times.empty(); }
  // The frame at or before time t (s); 0 when t precedes the first.
  size_t frameAt(double t) const;
};

class ThermalFrameRecorder {
 public:
  explicit ThermalFrameRecorder(double interval) : interval_(interval) {}
  void operator()(const ThermalStep& step);
  // Adds the end of the simulation (every element born by then) if it was not stored, and hands
  // the frames over.
  ThermalFrames take(const ThermalResult& result);

 private:
  void store(double time, const std::vector<double>& temperature, const std::vector<char>& deposited);

  double interval_;
  double next_ = 0.0;
  ThermalFrames frames_;
};

// An interval giving about `count` frames over `duration` seconds.
double frameIntervalFor(double duration, int count);

}  // namespace spira
