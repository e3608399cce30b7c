#include "spira/prep/deadband.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"

namespace spira {

DeadbandResult applyDeadband(const std::vector<double>& values, double threshold)
{
  if (!(threshold >= 0.0)) {
    throw InputError("the deadband threshold must be zero or more",
                     "set the output's deadband to its resolution, for example 0.05 in the channel's unit");
  }
  DeadbandResult r;
  r.emit.assign(values.size(), false);
  r.held.resize(values.size());
  double held = 0.0;
  for (size_t i = 0; i < values.size(); ++i) {
    if (i == 0 || std::abs(values[i] - held) > threshold) {
      held = values[i];
      r.emit[i] = true;
      ++r.emitted;
    }
    r.held[i] = held;
    r.maxError = std::max(r.maxError, std::abs(values[i] - held));
  }
  return r;
}

}  // namespace spira
