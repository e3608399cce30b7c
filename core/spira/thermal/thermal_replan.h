#pragma once

#include <string>

#include "spira/path/process_model.h"
#include "spira/thermal/thermal_study.h"

namespace spira {

// Thermal-aware re-planning (000_dbb97c2716e10cc3.txt §5.6.4 asks for a lower heat input where the
// part overheats). The "heat" remedy slows the wire feed and the travel speed together, by the same
// factor, over the revolutions whose interpass temperature exceeds the limit and the revolution
// under them: the bead's cross-section (WFS / TS) and so the deposit, the geometry and the single
// continuous spiral stay as planned, while the arc power (which follows the wire feed on a synergic
// line) drops and the torch takes longer to come back. It stops at the process limits.
struct ThermalReplanSettings {
  double interpassMax = 0.0;  // C
  ProcessLimits limits;       // the slowest wire feed and travel speed the process allows
  int maxRounds = 8;          // simulations after the first
};

struct ThermalReplanOutcome {
  Trajectory trajectory;  // the re-planned path (the input when the limit already held)
  ThermalStudy study;     // of `trajectory`
  bool limitMet = false;
  int rounds = 0;               // re-simulations
  int revolutionsChanged = 0;   // revolutions run slower
  int revolutionsAdded = 0;     // always 0 for this remedy: the geometry is kept
  double buildTimeAdded = 0.0;  // s
  double slowestFactor = 1.0;   // the lowest speed factor applied
  std::string why;              // when the limit is not met: what stopped the re-planning
};

// The arc's energy per mm of wire that makes `power` at the path's arc-on median wire feed, for a
// study whose power must follow the wire feed. InputError when the path has no wire feed.
double powerPerWireFeedOf(const Trajectory& trajectory, double power);

// Re-plans `planned` (with its process channels) until its interpass temperature stays at or under
// the limit or the process limits stop it. The power must follow the wire feed:
// `settings.solver.powerPerWireFeed` (see powerPerWireFeedOf) or a power table. Throws InputError for a limit
// at or below the initial temperature.
ThermalReplanOutcome replanForInterpass(const Trajectory& planned, const ThermalStudySettings& settings,
                                        const ThermalReplanSettings& replan, Progress& progress);

}  // namespace spira
