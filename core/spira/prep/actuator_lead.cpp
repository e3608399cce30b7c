#include "spira/prep/actuator_lead.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"
#include "spira/prep/channels.h"
#include "spira/prep/path_clock.h"

namespace spira {

namespace {

void checkModel(const LagModel& m)
{
  if (!(m.deadTime >= 0.0) || !(m.riseTimeConstant >= 0.0) || !(m.fallTimeConstant >= 0.0) ||
      !std::isfinite(m.deadTime) || !std::isfinite(m.riseTimeConstant) ||
      !std::isfinite(m.fallTimeConstant)) {
    throw InputError("the actuator dead time and time constants must be finite and zero or more",
                     "identify them with a step-bead test; typical wire feeders are below a second");
  }
  if (!(m.minCommand <= m.maxCommand)) {
    throw InputError("the actuator's minimum command is above its maximum",
                     "set min_command <= max_command (for example 0 and the feeder's top speed)");
  }
}

// Output after holding command c for dt from y0 (the lag's time constant depends on the direction).
double respond(double y0, double c, double dt, const LagModel& m)
{
  const double tau = c >= y0 ? m.riseTimeConstant : m.fallTimeConstant;
  if (tau <= 0.0) return c;
  return c + (y0 - c) * std::exp(-dt / tau);
}

}  // namespace

LeadResult leadChannel(const Trajectory& path, const std::vector<double>& planned, const LagModel& model)
{
  checkModel(model);
  const size_t n = path.size();
  if (planned.size() != n) {
    throw InputError("the planned channel has " + std::to_string(planned.size()) + " values for " +
                         std::to_string(n) + " path points",
                     "pass one planned value per trajectory point");
  }
  LeadResult r;
  if (n == 0) return r;
  const PathClock clock(path);
  r.time = clock.times();
  const std::vector<double>& t = r.time;
  const double td = model.deadTime;
  r.command.resize(n);
  r.triggerTime.resize(n);
  r.leadDistance.resize(n);
  r.predicted.assign(n, planned[0]);
  // A point reached exactly deadTime after the start still shows the start state.
  r.firstExactIndex =
      td > 0.0 ? static_cast<size_t>(std::upper_bound(t.begin(), t.end(), td) - t.begin()) : 0;

  // y: modelled output at the start of the current stretch of output time.
  double y = planned[0];
  for (size_t k = 0; k < n; ++k) {
    r.triggerTime[k] = std::max(0.0, t[k] - td);
    r.leadDistance[k] = clock.arcs()[k] - clock.arcAtTime(r.triggerTime[k]);
    if (k + 1 == n || t[k + 1] <= td) {
      // After the last point the value is simply held; stretches wholly before deadTime are out of reach.
      r.command[k] = k + 1 == n ? planned[k] : planned[0];
      continue;
    }
    const double dt = t[k + 1] - std::max(t[k], td);
    const double target = planned[k + 1];
    const double tau = target >= y ? model.riseTimeConstant : model.fallTimeConstant;
    double c = target;
    if (tau > 0.0 && dt > 0.0) {
      // Exact inverse of the lag over the stretch: target = c + (y - c) exp(-dt / tau).
      c = y + (target - y) / -std::expm1(-dt / tau);
    }
    if (c < model.minCommand || c > model.maxCommand) {
      c = std::clamp(c, model.minCommand, model.maxCommand);
      ++r.clampedCommands;
    }
    r.command[k] = c;
    y = dt > 0.0 ? respond(y, c, dt, model) : y;
    r.predicted[k + 1] = y;
  }

  r.commandAtPoint.resize(n);
  // A trigger due within a nanosecond of passing a point counts as written there: at constant speed
  // triggers and points coincide, up to the rounding of the summed times.
  constexpr double kTie = 1e-9;
  size_t active = 0;
  for (size_t k = 0; k < n; ++k) {
    while (active + 1 < n && r.triggerTime[active + 1] <= t[k] + kTie) ++active;
    r.commandAtPoint[k] = r.command[active];
  }
  for (size_t k = r.firstExactIndex; k < n; ++k)
    r.maxError = std::max(r.maxError, std::abs(r.predicted[k] - planned[k]));
  return r;
}

LeadResult leadChannel(const Trajectory& path, const std::string& channel, const LagModel& model)
{
  return leadChannel(path, channelValues(path, channel), model);
}

}  // namespace spira
