#pragma once

#include <map>
#include <string>

#include "spira/base/units.h"
#include "spira/prep/actuator_lead.h"

namespace spira {

// Settings of the path preparation run before a robot program is written: C2 quintic smoothing
// (002_4d923f9355c20a15.txt §I.2.1.1), resampling of the quintic at a chordal tolerance, then greedy
// point skipping (§I.3) under a chord tolerance and per-channel attribute tolerances, so that
// deposit-height modulation survives the decimation (A.4.2). Internal units: mm, mm/s, rad.
struct PrepParams {
  // --- smoothing (A.2.1) ---
  // Replace the polyline by the sliding quintic through its points (positions and the n, t, b
  // frame vectors). Off: the points are decimated as they are. Default true.
  bool smooth = true;
  // Chord error (mm) allowed between the quintic and the dense samples taken on it; the decimation
  // then measures its tolerances against those samples. Default 0.01 mm.
  double resampleTolerance = 0.01;
  // A source point where the path turns by more than this (rad) stays a sharp corner: the parabola
  // rule would otherwise round it and overshoot. Default 60 deg.
  double cornerAngle = degToRad(60.0);

  // --- decimation (002_4d923f9355c20a15.txt §I.3; 004_bd0df31205c0c3c0.txt §3.2.1) ---
  // Greatest distance (mm) of a dropped sample from the robot's straight segment. Default 0.05 mm
  // (A.4.2 suggests 0.02-0.1 mm for WAAM).
  double chordTolerance = 0.05;
  // Greatest deviation of the linearly interpolated channel from a dropped sample. Defaults:
  // deposit height 0.02 mm, travel speed 0.2 mm/s, wire feed 1.0 mm/s (0.06 m/min).
  double heightTolerance = 0.02;
  double travelSpeedTolerance = 0.2;
  double wireFeedTolerance = 1.0;
  // Greatest angle (rad) between the slerp-interpolated tool frame and a dropped sample's frame.
  // Default 1 deg.
  double orientationTolerance = degToRad(1.0);
  // Tolerance of an `extra` channel, in that channel's unit, by name; channels not listed get
  // `extraTolerance`. Default empty / 0.01.
  std::map<std::string, double> extraTolerances;
  double extraTolerance = 0.01;
  // Consecutive output points are at least `minSpacing` (mm, along the path) apart unless one of
  // them must be kept (ends, arc switches...); near-duplicates make the robot slow down. Default 0.5 mm.
  double minSpacing = 0.5;
  // ... and at most `maxSpacing` (mm, along the path): Chalvin measured that a robot's form error is
  // driven by point spacing and recommends about 4.9 mm at most. Default 5 mm; must be finite.
  double maxSpacing = 5.0;
  // Keep the first point of every revolution (a layer start the exporter may mark). Default false.
  bool keepRevolutionStarts = false;

  // --- export of the prepared path (pipeline/export_job.h) ---
  // Lead the wire-feed channel by the feeder's lag (actuator_lead.h): each setpoint is written
  // early enough for the modelled output to reach the planned value at its point. Default off.
  bool leadWireFeed = false;
  LagModel wireFeedLag;
  // Between the sub-paths of a multi-branch plan the torch backs off along its axis by
  // `travelClearance` (mm), rises to `travelClearance` above the plan's highest point, travels
  // there with the arc off and comes down the same way to the next sub-path, at `travelSpeed`
  // (mm/s). Defaults 30 mm and 50 mm/s.
  double travelClearance = 30.0;
  double travelSpeed = 50.0;
};

}  // namespace spira
