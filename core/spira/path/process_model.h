#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "spira/base/units.h"
#include "spira/path/calibration_table.h"
#include "spira/path/trajectory.h"

namespace spira {

// Which process channel carries the height modulation.
enum class ProcessMode {
  Synergic,             // constant wire feed, travel speed modulated (the thesis's CMT synergic choice)
  ConstantTravelSpeed,  // constant travel speed, wire feed modulated
};

// How a deposit height becomes a speed.
enum class HeightModel {
  // Thesis Eq. 4.1 with a steady wall of width W: LH = pi d^2 WFS / (4 W TS).
  MassConservation,
  // The user's measured height -> travel speed table at the wire feed `ProcessSettings::wireFeed`.
  // In constant-travel-speed mode the wire feed follows from it as WFS = wireFeed * TS / TS_table(h):
  // the bead is taken to depend on WFS / TS only, as mass conservation at constant width implies.
  Calibration,
};

// The thesis's wall width at 2.3 m/min (Fig. 4.3), mm.
inline constexpr double kDefaultBeadWidth = 5.2;

// The default limits are the product's (plan_schemas.cpp); unlimited speeds are set explicitly.
struct ProcessLimits {
  double travelSpeedMin = 0.5;            // mm/s
  double travelSpeedMax = 50.0;           // mm/s
  double wireFeedMin = 0.5 * 1000 / 60;   // mm/s (0.5 m/min)
  double wireFeedMax = 20.0 * 1000 / 60;  // mm/s (20 m/min)
};

struct ProcessSettings {
  ProcessMode mode = ProcessMode::Synergic;
  HeightModel model = HeightModel::MassConservation;
  double wireDiameter = 1.0;             // d, mm (the thesis's G3Si wire)
  double beadWidth = kDefaultBeadWidth;  // W, mm
  double wireFeed = 2300.0 / 60.0;       // mm/s: held in synergic mode; the table's wire feed
  double travelSpeed = 5.0;              // mm/s: held in constant-travel-speed mode
  CalibrationTable calibration;          // HeightModel::Calibration only
  ProcessLimits limits;
  // Speeds beyond the limits are reported and, when set, clamped to the limit, so the channels stay
  // executable (the ramps' seam points near a closure point ask for a nearly zero deposit, i.e. an
  // unbounded travel speed). The report keeps the requested value.
  bool clampToLimits = true;
  // The robot controller may slow the travel below the plan where an axis would pass its speed
  // limit (the wire feed keeps its setpoint). Not used here: the motion check reports the thicker
  // deposit that follows (slowdown_deposit.h); off, an axis over its limit makes the plan infeasible.
  bool allowSlowdown = false;
  // How far from the vertical (rad) a positioner may leave the build direction (the flat welding
  // position); within it the table's rotation is free, so a spiral's climb does not whip it round.
  double positionerTiltTolerance = degToRad(2.0);
  // The torch's angles off the build direction (rad, tool_tilt.h): lead towards the travel direction
  // (push positive), side towards the surface normal. Zero: the torch follows b, as in the source's
  // experiments.
  double torchLead = 0.0;
  double torchSide = 0.0;
};

enum class ProcessViolationKind {
  TravelSpeedBelowMin,
  TravelSpeedAboveMax,
  WireFeedBelowMin,
  WireFeedAboveMax,
  HeightOutsideCalibration,  // speeds taken from the nearest end of the table
  HeightNotPositive,         // no speed maps to it; the previous point's speeds are kept
};
const char* processViolationName(ProcessViolationKind kind);  // stable snake_case name

struct ProcessViolation {
  size_t point = 0;
  ProcessViolationKind kind = ProcessViolationKind::TravelSpeedAboveMax;
  double value = 0.0;  // the offending speed (mm/s) or height (mm)
  double limit = 0.0;  // the bound it crosses
};

struct ProcessReport {
  double buildTime = 0.0;      // s, each segment at the (clamped) travel speed of its first point, + dwells
  size_t dwells = 0;           // points with a dwell (path/dwell.h)
  double dwellTime = 0.0;      // s: their waits, in buildTime (the lift and return moves are the program's)
  double wireLength = 0.0;     // mm of wire fed over the build
  double depositVolume = 0.0;  // mm^3: wireLength * pi d^2 / 4
  double travelSpeedMin = 0.0, travelSpeedMax = 0.0;  // mm/s
  double wireFeedMin = 0.0, wireFeedMax = 0.0;        // mm/s
  std::vector<ProcessViolation> violations;
  bool withinLimits = true;  // no violation of any kind
};

// Mass conservation (Eq. 4.1 over a wall of width W), d and W in mm, speeds in mm/s.
double massConservationHeight(double wireDiameter, double beadWidth, double wireFeed, double travelSpeed);
double massConservationTravelSpeed(double wireDiameter, double beadWidth, double wireFeed, double height);
double massConservationWireFeed(double wireDiameter, double beadWidth, double travelSpeed, double height);

// Fills travelSpeed and wireFeed of every point from its height channel, switches the arc on from
// the first to the last point and checks the limits (clamping, see ProcessSettings). Throws InputError for
// non-positive or non-finite diameter, width or held speed, crossed limits, or the calibration model without
// a table. Limit violations are not errors: they are listed by point in the report.
ProcessReport applyProcess(Trajectory& path, const ProcessSettings& settings);

}  // namespace spira
