#pragma once

#include <string>
#include <vector>

#include "spira/path/process_model.h"
#include "spira/thermal/thermal_study.h"

namespace spira {

// Thermal-aware re-planning: where the interpass temperature exceeds a limit, the plan changes and
// the build is simulated again until the limit holds or the remedies run out. The remedies, applied
// in this order when several are chosen, each from the path the previous one left:
//  - deposit: the source's own (000_dbb97c2716e10cc3.txt §5.6.4): the band of revolutions that
//    overheats is laid with more, thinner revolutions at the same wire feed, so a higher travel
//    speed (revolution_thinning.h); no thinner than the process window's h_min allows, nor faster
//    than its fastest travel. The path stays one continuous spiral.
//  - heat: the wire feed and the travel speed slowed together, by the same factor, over the
//    revolutions above the limit and the one under them: the deposit and the geometry stay as
//    planned, the arc power (which follows the wire feed on a synergic line) drops and the torch
//    takes longer to come back. Down to the process's slowest speeds. One continuous spiral still.
//  - dwell: the torch stops at the end of the revolution under each one above the limit, lifts
//    away with the arc off and waits (dwell.h) until the part has cooled enough. Each dwell adds an
//    arc start: the spiral is no longer one continuous deposit.
struct ThermalReplanSettings {
  double interpassMax = 0.0;  // C
  bool deposit = false, heat = true, dwell = false;
  ProcessLimits limits;     // the slowest wire feed and travel speed (heat), the fastest travel (deposit)
  double hMin = 0.0;        // thinnest deposit of the process window, mm (deposit; 0 stops the remedy)
  double maxDwell = 600.0;  // longest single wait, s
  int maxRounds = 8;        // simulations after the first
};

struct ThermalReplanOutcome {
  Trajectory trajectory;  // the re-planned path (the input when the limit already held)
  ThermalStudy study;     // of `trajectory`
  bool limitMet = false;
  int rounds = 0;                    // re-simulations
  std::vector<std::string> applied;  // the remedies that changed the path, in order
  int revolutionsAdded = 0;          // deposit: revolutions the thinner band added
  double thinnestRatio = 1.0;        // deposit: the band's mean deposit over the planned one
  int revolutionsChanged = 0;        // heat: revolutions run slower
  double slowestFactor = 1.0;        // heat: the lowest speed factor applied
  int dwells = 0;                    // dwell: stops added (each one more arc start)
  double dwellTime = 0.0;            // dwell: their waits summed, s
  double buildTimeAdded = 0.0;       // s
  double plannedWorst = 0.0;         // C: the planned path's highest interpass temperature
  std::string why;                   // when the limit is not met: what stopped the re-planning
};

// The arc's energy per mm of wire that makes `power` at the path's arc-on median wire feed, for a
// study whose power must follow the wire feed. InputError when the path has no wire feed.
double powerPerWireFeedOf(const Trajectory& trajectory, double power);

std::string remediesText(const ThermalReplanSettings& settings);  // the chosen ones: "deposit,heat"

// Re-plans `planned` (with its process channels) until its interpass temperature stays at or under
// the limit or the remedies are spent. The power must follow the wire feed:
// `settings.solver.powerPerWireFeed` (see powerPerWireFeedOf) or a power table. Throws InputError for a
// limit at or below the initial temperature, or no remedy chosen. When the limit is not met the
// outcome holds the path with the lowest worst interpass temperature simulated.
ThermalReplanOutcome replanForInterpass(const Trajectory& planned, const ThermalStudySettings& settings,
                                        const ThermalReplanSettings& replan, Progress& progress);

}  // namespace spira
