#pragma once

#include <array>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/base/transform.h"
#include "spira/plugin/exporter.h"

namespace spira {

// Optional trajectory channels (Trajectory::extra) with a led wire feed (pipeline/export_job.h):
// the setpoint due at each point (mm/s) and how long (s) before reaching the point it must be
// written so that the feeder's modelled output reaches the planned value there.
inline constexpr const char* kWfsCommandChannel = "wfs_command";
inline constexpr const char* kWfsLeadChannel = "wfs_lead_s";

// How the process is commanded along the path.
enum class ProcessCommand {
  Speed,        // per-move speed from the TS channel; the weld job sets the wire feed
  SpeedAnalog,  // per-move speed, and the WFS channel on an analog output
  Analog,       // one constant speed (the first deposition move's), WFS on an analog output
};

// The settings every exporter shares (see export_params.h for their schema entries).
struct PathOptions {
  std::string controller;         // "kuka_krc4", "fanuc_r30ib" or "abb_irc5": a joint trajectory must match
  double approachDistance = 0.0;  // mm back along the torch axis; 0 = start and end on the path
  double approachSpeed = 20.0;    // mm/s on the approach and retract moves
  ProcessCommand process = ProcessCommand::Speed;
  double wfsDeadband = 0.0;  // mm/s: a WFS setpoint is written only when WFS moved this much
  bool force = false;        // export even with unreachable, colliding or out-of-limit points
};

// One path point as the writers need it. Move k is the motion INTO point k.
struct ExportPoint {
  // The target: T_base_tcp from the solved cell (controller base frame), or without a cell the
  // torch frame in the part frame (toolFrame with spin 0). mm.
  Transform pose = Transform::Identity();
  double speed = 0.0;     // mm/s of move k in the target's frame (the TS channel for a fixed part)
  double moveTime = 0.0;  // s: planned duration of move k, |part-frame step| / TS (0 for point 0)
  double wfs = 0.0;       // mm/s, the WFS channel of point k (the led setpoint with a lead)
  bool writeWfs = false;  // analog modes: the WFS setpoint of move k must be written (deadband)
  double wfsLead = 0.0;   // s: with a lead, the setpoint is written this long before reaching k
  int path = 0;           // sub-path index (the trajectory's path channel)
  bool inArc = false;     // the arc burns at this point (between a strike and a stop, both included)
  bool strike = false;    // the arc is struck here (first point of an arc)
  bool stop = false;      // the arc is put out here (last point of an arc)
  bool transfer = false;  // move k changes sub-path: a joint move (the arm configuration may change)
  double dwell = 0.0;     // s: the torch waits here, arc off, after move k (a dwell's lift, path/dwell.h)
  std::array<double, 6> robotDeg{};
  std::array<double, 2> externalDeg{};
  int kukaStatus = 0;
  int kukaTurn = 0;
  std::string fanucConfig;
  std::array<int, 4> abbConf{};  // cf1, cf4, cf6, cfx
  std::string problem;           // "unreachable", "in collision", "A5 outside its limits"...; empty when fine
};

// The trajectory checked and turned into controller-ready targets, shared by the exporters.
struct ExportPath {
  std::vector<ExportPoint> points;             // one per trajectory point, same order
  Transform approach = Transform::Identity();  // = points.front().pose when there is no approach
  Transform retract = Transform::Identity();   // = points.back().pose when there is no retract
  bool hasApproach = false;
  size_t arcStart = 0;   // first point with the arc on: the first arc is struck there
  size_t arcEnd = 0;     // last point with the arc on: the last arc is put out there
  size_t arcCount = 0;   // arcs: one per sub-path and one more per dwell inside one (strike/stop flags)
  bool hasLead = false;  // the wire feed is led (kWfsLeadChannel): setpoints carry wfsLead
  bool hasJoints = false;
  bool hasPositioner = false;
  size_t flaggedCount = 0;  // points with a problem (written only when forced)
  double length = 0.0;      // mm, part frame
  std::vector<std::string> warnings;
};

// Checks `input` against `options` and builds the targets. Every sub-path (a run of one `path`
// index) gets one arc, from its first to its last arc-on point; its points before and after that
// (travel moves) and the move between sub-paths run with the arc off and write no process output.
// A wait (the dwell channel of path/dwell.h, > 0 only at arc-off points: the lifts that
// exportTrajectory lays out) cuts a sub-path's arc in two: the arc stops before it and is struck
// again after it.
// Throws InputError when the plan
// cannot be exported: fewer than two points, no deposition (arc on at fewer than two points),
// non-finite or non-positive channels, a wait at an arc-on point, a joint trajectory of another size or
// controller; and InfeasibleError (unless options.force) for points that are unreachable, in collision or
// outside joint limits. Recoverable findings (joint speeds over the limits, configuration changes, arc gaps)
// are returned as warnings.
ExportPath prepareExportPath(const ExportInput& input, const PathOptions& options, Progress& progress);

}  // namespace spira
