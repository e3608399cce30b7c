#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace spira {

// Wall-clock seconds per stage, in pipeline order.
using StageTimings = std::vector<std::pair<std::string, double>>;

// Appends the time since the previous lap (or construction) to `timings` under a stage name.
class StageClock {
 public:
  explicit StageClock(StageTimings& timings) : timings_(timings) {}
  void lap(const std::string& stage)
  {
    const auto now = std::chrono::steady_clock::now();
    timings_.emplace_back(stage, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  StageTimings& timings_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace spira
