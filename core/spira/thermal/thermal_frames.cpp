#include "spira/thermal/thermal_frames.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace spira {

size_t ThermalFrames::frameAt(double t) const
{
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  return it == times.begin() ? 0 : size_t(it - times.begin()) - 1;
}

void ThermalFrameRecorder::store(double time, const std::vector<double>& temperature,
                                 const std::vector<char>& deposited)
{
  std::vector<float> frame(temperature.size());
  for (size_t i = 0; i < frame.size(); ++i)
    frame[i] = deposited[i] ? float(temperature[i]) : std::numeric_limits<float>::quiet_NaN();
  frames_.times.push_back(time);
  frames_.values.push_back(std::move(frame));
}

void ThermalFrameRecorder::operator()(const ThermalStep& step)
{
  if (step.time + 1e-9 < next_) return;
  store(step.time, step.temperature, step.deposited);
  next_ = interval_ > 0.0 ? (std::floor(step.time / interval_ + 1e-9) + 1.0) * interval_
                          : std::numeric_limits<double>::infinity();
}

ThermalFrames ThermalFrameRecorder::take(const ThermalResult& result)
{
  if (frames_.times.empty() || frames_.times.back() < result.simulatedTime - 1e-9)
    store(result.simulatedTime, result.finalTemperature,
          std::vector<char>(result.finalTemperature.size(), 1));
  return std::move(frames_);
}

double frameIntervalFor(double duration, int count)
{
  return duration > 0.0 && count > 0 ? duration / count : 0.0;
}

}  // namespace spira
