#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "spira/path/trajectory.h"

namespace spira {

// A process actuator (wire feeder, power source input) as dead time plus first-order lag
// (003_abf6ea7743219370.txt §3.2.3, Eq. 3.12-3.13): the output y follows the command u as
//   tau * dy/dt + y = u(t - deadTime),
// with tau = riseTimeConstant while y rises and fallTimeConstant while it falls. Identify the values
// with a step-bead test (a WFS step, the bead height profile converted from distance to time).
struct LagModel {
  double deadTime = 0.1;          // s, controller and I/O latency. Default 0.1 s
  double riseTimeConstant = 0.1;  // s, first-order lag while the output rises. Default 0.1 s
  double fallTimeConstant = 0.1;  // s, while it falls. Default 0.1 s
  // Commands the actuator accepts, in the channel's unit. Default [0, +inf).
  double minCommand = 0.0;
  double maxCommand = std::numeric_limits<double>::infinity();
};

// Setpoints that make the modelled actuator output equal the planned channel at every point it can
// reach. Commands are held between triggers (the robot writes a setpoint, the actuator keeps it);
// command[k] is meant to act from the moment the output is due at point k to the next point, so it
// is written deadTime earlier: at time triggerTime[k], leadDistance[k] of path before point k (a
// path-synchronised trigger, KUKA TRIGGER WHEN PATH / Fanuc distance-before, so the look-ahead never
// stops). Inside each stretch it is the exact inverse of the lag: y(t_{k+1}) = planned[k+1].
//
// Before the motion the actuator is assumed settled at planned[0]. Points reached sooner than
// deadTime after the start cannot be led (their output is still planned[0]); firstExactIndex is the
// first point from which the output is exact, unless a command hit minCommand/maxCommand.
struct LeadResult {
  std::vector<double> time;            // s, when the robot passes each point (0 at the first; PathClock)
  std::vector<double> command;         // setpoint for the stretch from point k to k + 1
  std::vector<double> triggerTime;     // s, max(0, time[k] - deadTime)
  std::vector<double> leadDistance;    // mm of path from the trigger position to point k, >= 0
  std::vector<double> commandAtPoint;  // the led channel: the setpoint in force as the robot passes k
  std::vector<double> predicted;       // modelled actuator output at each point
  size_t firstExactIndex = 0;
  size_t clampedCommands = 0;
  double maxError = 0.0;  // max |predicted - planned| from firstExactIndex on
};

LeadResult leadChannel(const Trajectory& path, const std::vector<double>& planned, const LagModel& model);
LeadResult leadChannel(const Trajectory& path, const std::string& channel, const LagModel& model);

}  // namespace spira
