#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "spira/base/transform.h"

namespace spira {

// What each stage of a plan reports, as typed values held by Results. report.json and the project
// file store them through stage_report_codec.h, under the keys each `fields` lists: that list is
// the one place a key is written. A codec `Io` is called as io(key, member) for a member always
// written, io.optional(key, member) for one left out when empty and io.nullable(key, member) for
// one written as null when empty. A double that is not finite is written as null and read back
// as NaN (a turn on the spot needs an infinite axis speed).

using SecondsPerStep = std::map<std::string, double>;  // wall time per step, s

struct DepositFlagRecord {
  std::int64_t point = 0;
  std::string kind;     // "below_deposit", "thin", "thick", "jump", "unsupported"
  double height = 0.0;  // mm: what lies below, or the jump's length; NaN: nothing below
  Vec3 position = Vec3::Zero();
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("point", s.point), io("kind", s.kind), io("height", s.height), io("position", s.position);
  }
};

struct CoverageRecord {
  double surfaceArea = 0.0, uncoveredArea = 0.0, uncoveredFraction = 0.0;  // mm^2, mm^2, share
  double coverRadius = 0.0, largestGap = 0.0;                              // mm
  Vec3 largestGapAt = Vec3::Zero();
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("surface_area_mm2", s.surfaceArea), io("uncovered_area_mm2", s.uncoveredArea);
    io("uncovered_fraction", s.uncoveredFraction), io("cover_radius_mm", s.coverRadius);
    io("largest_gap_mm", s.largestGap), io("largest_gap_at", s.largestGapAt);
  }
};

// The deposit check's verdict on the path (verify/deposit_check.h), its first 1000 flags.
struct DepositCheckRecord {
  bool feasible = false;
  std::string summary;
  std::int64_t pointsChecked = 0;
  double heightMin = 0.0, heightMax = 0.0, heightMean = 0.0, plannedDifferenceMax = 0.0, jumpLength = 0.0;
  std::map<std::string, std::int64_t> counts;  // per defect kind
  std::int64_t flagged = 0;                    // all flagged points, listed or not
  std::vector<DepositFlagRecord> flaggedPoints;
  std::optional<CoverageRecord> coverage;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("feasible", s.feasible), io("summary", s.summary), io("points_checked", s.pointsChecked);
    io("height_min", s.heightMin), io("height_max", s.heightMax), io("height_mean", s.heightMean);
    io("planned_difference_max", s.plannedDifferenceMax), io("jump_length", s.jumpLength);
    io("counts", s.counts), io("flagged", s.flagged), io("flagged_points", s.flaggedPoints);
    io.optional("coverage", s.coverage);
  }
};

struct WallThicknessRecord {
  double median = 0.0, thinnest = 0.0, thickest = 0.0;  // mm
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("median", s.median), io("thinnest", s.thinnest), io("thickest", s.thickest);
  }
};

// A thin-walled solid planned on its mid-surface.
struct SolidRecord {
  std::string kind = "thin_walled_solid", plannedOn = "mid_surface";
  WallThicknessRecord wallThickness;
  double wallAreaFraction = 0.0, beadWidth = 0.0;
  std::int64_t solidFaces = 0, midSurfaceFaces = 0;
  std::vector<std::string> warnings;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("kind", s.kind), io("planned_on", s.plannedOn), io("wall_thickness_mm", s.wallThickness);
    io("wall_area_fraction", s.wallAreaFraction), io("bead_width_mm", s.beadWidth);
    io("solid_faces", s.solidFaces), io("mid_surface_faces", s.midSurfaceFaces), io("warnings", s.warnings);
  }
};

// Thesis Eq. 3.6 as the spiral applied it.
struct LengthCriterionRecord {
  double lengthMin = 0.0, lengthMax = 0.0, stepSpread = 0.0, window = 0.0;  // mm
  std::int64_t layers = 0;
  bool ok = false;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("length_min", s.lengthMin), io("length_max", s.lengthMax), io("n_layers", s.layers);
    io("step_spread", s.stepSpread), io("window", s.window), io("ok", s.ok);
  }
};

// A point whose planned height leaves the window (the first 1000 of them).
struct WindowViolationRecord {
  std::int64_t point = 0, revolution = 0, generatrix = 0;
  double height = 0.0;  // mm
  std::string phase;    // "start_up", "modulated", "termination", "closure"
  bool above = false;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("point", s.point), io("revolution", s.revolution), io("generatrix", s.generatrix);
    io("height", s.height), io("phase", s.phase), io("above", s.above);
  }
};

// One sub-path of a plan (planning/planner.h PathSummary).
struct PathRecord {
  std::int64_t path = 0, parent = -1, depth = 0;
  std::string role, partType;  // "trunk" or "branch"; "open" or "closed"
  double baseLevel = 0.0, area = 0.0;
  std::int64_t firstPoint = 0, points = 0, generatrices = 0, revolutions = 0;
  double generatrixLengthMin = 0.0, generatrixLengthMax = 0.0;
  double heightMin = 0.0, heightMax = 0.0, heightMean = 0.0;
  bool feasible = false;
  std::int64_t depositFlags = 0, violations = 0;
  double pathLength = 0.0, maxJump = 0.0, buildTime = 0.0;
  std::optional<Vec3> closurePoint;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("path", s.path), io("parent", s.parent), io("depth", s.depth), io("role", s.role);
    io("part_type", s.partType), io("base_level", s.baseLevel), io("area_mm2", s.area);
    io("first_point", s.firstPoint), io("n_points", s.points), io("n_generatrices", s.generatrices);
    io("generatrix_length_min", s.generatrixLengthMin), io("generatrix_length_max", s.generatrixLengthMax);
    io("n_revolutions", s.revolutions), io("height_min", s.heightMin), io("height_max", s.heightMax);
    io("height_mean", s.heightMean), io("feasible", s.feasible), io("deposit_flags", s.depositFlags);
    io("violations", s.violations), io("path_length", s.pathLength), io("max_jump", s.maxJump);
    io("build_time_s", s.buildTime), io.nullable("closure_point", s.closurePoint);
  }
};

struct SaddleRecord {
  std::int64_t belowPath = 0, branches = 0, bisections = 0;
  double level = 0.0, trunkTopLevel = 0.0, branchBaseLevel = 0.0, gapArea = 0.0;
  Vec3 position = Vec3::Zero();
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("below_path", s.belowPath), io("level", s.level), io("position", s.position);
    io("branches", s.branches), io("trunk_top_level", s.trunkTopLevel);
    io("branch_base_level", s.branchBaseLevel), io("gap_area_mm2", s.gapArea), io("bisections", s.bisections);
  }
};

// How a multi-branch part was split.
struct BranchingRecord {
  std::vector<SaddleRecord> saddles;
  double junctionGap = 0.0, junctionGapArea = 0.0;  // mm, mm^2
  bool depthLimited = false;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("saddles", s.saddles), io("junction_gap_mm", s.junctionGap);
    io("junction_gap_area_mm2", s.junctionGapArea), io("depth_limited", s.depthLimited);
  }
};

// The field stage: which field, how long it took, the closure point of a closed part.
struct FieldStageReport {
  std::string kind;  // "geodesic_distance" or "harmonic"
  SecondsPerStep timings;
  std::optional<Vec3> closurePoint;
  std::optional<double> closureDistance;  // mm
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("kind", s.kind), io("timings_s", s.timings), io.optional("closure_point", s.closurePoint);
    io.optional("closure_distance", s.closureDistance);
  }
};

struct GeneratricesStageReport {
  std::int64_t count = 0;
  double lengthMin = 0.0, lengthMax = 0.0;  // mm
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("n_generatrices", s.count), io("generatrix_length_min", s.lengthMin);
    io("generatrix_length_max", s.lengthMax);
  }
};

// The spiral stage: the plan's figures and verdict, with the window it was planned for (the top
// level of report.json).
struct SpiralStageReport {
  std::string partType, strategy, field;
  std::int64_t generatrices = 0;
  double generatrixLengthMin = 0.0, generatrixLengthMax = 0.0;
  std::int64_t startupRevolutions = 0, layers = 0, endRevolutions = 0, revolutions = 0, points = 0;
  std::int64_t collapsedRevolutions = 0;  // folded into the closure point, not laid
  double stepMin = 0.0, stepMax = 0.0, heightMin = 0.0, heightMax = 0.0, heightMean = 0.0;
  double rampHeightMin = 0.0, rampHeightMax = 0.0;  // 0: no start-up or closing ramp
  double h = 0.0, hMin = 0.0, hMax = 0.0, heightTolerance = 0.0;
  bool feasible = false;  // the deposit check's verdict
  bool windowFeasible = false;
  DepositCheckRecord depositCheck;
  std::optional<SolidRecord> solid;
  LengthCriterionRecord lengthCriterion;
  std::int64_t violations = 0, modulatedViolations = 0;
  double closureGap = 0.0;
  std::vector<WindowViolationRecord> violationPoints;
  std::optional<Vec3> closurePoint;
  std::optional<double> closureDistance;
  double pathLength = 0.0, maxJump = 0.0, seamRiseMax = 0.0, buildTime = 0.0;
  std::optional<std::int64_t> dwells;  // with a dwell (path/dwell.h): how many, and their waits
  std::optional<double> dwellTime;     // s, included in buildTime
  // Laid in layers (decomposer.constant_distance): each layer point's distance to the layer below, mm, the
  // largest turning angle within a layer (overall and per layer), the arcs, the path and how it ended.
  std::optional<double> deltaMin, deltaMax, maxKinkDeg;
  std::optional<std::vector<double>> layerKinksDeg;
  std::optional<std::int64_t> arcStarts;
  std::optional<std::string> layerOutput, layerEnd;
  SecondsPerStep timings;  // per planning stage, with "total"
  std::vector<std::string> warnings;
  std::int64_t pathCount = 1;
  std::vector<PathRecord> paths;
  std::optional<BranchingRecord> branching;

  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("part_type", s.partType), io("strategy", s.strategy), io("field", s.field);
    io("n_generatrices", s.generatrices), io("generatrix_length_min", s.generatrixLengthMin);
    io("generatrix_length_max", s.generatrixLengthMax), io("n_startup_revolutions", s.startupRevolutions);
    io("n_layers", s.layers), io("n_end_revolutions", s.endRevolutions), io("n_revolutions", s.revolutions);
    io("n_points", s.points), io("step_min", s.stepMin), io("step_max", s.stepMax);
    io("height_min", s.heightMin), io("height_max", s.heightMax), io("height_mean", s.heightMean);
    io("ramp_height_min", s.rampHeightMin), io("ramp_height_max", s.rampHeightMax);
    io("h", s.h), io("h_min", s.hMin), io("h_max", s.hMax), io("height_tolerance_mm", s.heightTolerance);
    io("collapsed_revolutions", s.collapsedRevolutions), io("feasible", s.feasible);
    io("window_feasible", s.windowFeasible), io("deposit_check", s.depositCheck);
    io.optional("solid", s.solid), io("length_criterion", s.lengthCriterion);
    io("violations", s.violations), io("modulated_violations", s.modulatedViolations);
    io("closure_gap", s.closureGap), io("violation_points", s.violationPoints);
    io.nullable("closure_point", s.closurePoint), io.optional("closure_distance", s.closureDistance);
    io("path_length", s.pathLength), io("max_jump", s.maxJump), io("seam_rise_max", s.seamRiseMax);
    io("build_time_s", s.buildTime), io.optional("n_dwells", s.dwells);
    io.optional("dwell_time_s", s.dwellTime), io.optional("delta_min", s.deltaMin);
    io.optional("delta_max", s.deltaMax), io.optional("max_kink_deg", s.maxKinkDeg);
    io.optional("layer_kinks_deg", s.layerKinksDeg), io.optional("n_arc_starts", s.arcStarts);
    io.optional("layer_output", s.layerOutput), io.optional("part_end", s.layerEnd);
    io("timings_s", s.timings), io("warnings", s.warnings);
    io("n_paths", s.pathCount), io("paths", s.paths), io.optional("branching", s.branching);
  }
};

// The process stage: speeds and wire against the machine's limits (report.json's "process").
struct ProcessStageReport {
  bool withinLimits = true;
  double travelSpeedMin = 0.0, travelSpeedMax = 0.0;  // mm/s
  double wireFeedMin = 0.0, wireFeedMax = 0.0;        // m/min
  double wireLength = 0.0, depositVolume = 0.0;       // mm, mm^3
  std::int64_t limitViolations = 0;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("within_limits", s.withinLimits), io("ts_min_mm_s", s.travelSpeedMin);
    io("ts_max_mm_s", s.travelSpeedMax), io("wfs_min_m_min", s.wireFeedMin);
    io("wfs_max_m_min", s.wireFeedMax), io("wire_length_mm", s.wireLength);
    io("deposit_volume_mm3", s.depositVolume), io("limit_violations", s.limitViolations);
  }
};

// The thermal stage: the heat of the build along the path (thermal.md), its summary; the per-point
// and per-node values are the stage's result (thermal_result.h). Keys as `spira-cli thermal` writes
// them in thermal.json.
struct ThermalStageReport {
  std::string material;
  double meltingTemperature = 0.0, power = 0.0;  // C, W
  double interpassLimit = 0.0;                   // C; 0: none set
  double maxPeak = 0.0, maxInterpass = 0.0;      // C
  double maxPoolLength = 0.0, maxBond = 0.0, bondThreshold = 0.0;
  std::int64_t riskPoints = 0, pointsOverLimit = 0;
  double energyIn = 0.0, energyStored = 0.0, energyLost = 0.0;  // J
  std::int64_t nodes = 0, elements = 0, steps = 0;
  double simulatedTime = 0.0;  // s
  // With an interpass limit and re-planning: whether the re-planned path meets it, and its cost.
  std::optional<bool> limitMet;
  std::optional<std::int64_t> revolutionsAdded;
  std::optional<double> buildTimeAdded;                     // s
  std::optional<std::vector<std::string>> remediesApplied;  // "deposit", "heat", "dwell"
  std::optional<std::int64_t> dwells;                       // each one more arc start
  std::optional<double> dwellTime;                          // s
  std::optional<std::string> whyNotMet;
  // The re-planned path judged again when the re-planning changed its geometry (the deposit remedy):
  // it is the path the plan executes, so its verdict is the plan's.
  std::optional<DepositCheckRecord> depositCheck;
  SecondsPerStep timings;  // mesh, simulation, solver
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("material", s.material), io("melting_C", s.meltingTemperature), io("power_W", s.power);
    io("interpass_limit_C", s.interpassLimit), io("max_peak_C", s.maxPeak);
    io("max_interpass_C", s.maxInterpass), io("max_pool_length_mm", s.maxPoolLength);
    io("max_bond", s.maxBond), io("bond_threshold", s.bondThreshold), io("n_risk_points", s.riskPoints);
    io("n_points_over_limit", s.pointsOverLimit), io("energy_in_J", s.energyIn);
    io("energy_stored_J", s.energyStored), io("energy_lost_J", s.energyLost), io("n_nodes", s.nodes);
    io("n_elements", s.elements), io("n_steps", s.steps), io("simulated_time_s", s.simulatedTime);
    io.optional("limit_met", s.limitMet), io.optional("revolutions_added", s.revolutionsAdded);
    io.optional("build_time_added_s", s.buildTimeAdded), io.optional("remedies_applied", s.remediesApplied);
    io.optional("dwells", s.dwells), io.optional("dwell_time_s", s.dwellTime);
    io.optional("why_not_met", s.whyNotMet), io.optional("deposit_check", s.depositCheck);
    io("timings_s", s.timings);
  }
};

struct AxisSpeedRecord {
  double maxPercent = 0.0;  // of the axis's speed limit
  std::optional<std::int64_t> point;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("max_percent", s.maxPercent), io.nullable("point", s.point);
  }
};

// A point the controller slows down: [index, factor, height_mm, slowed_height_mm, fits].
struct SlowedPointRecord {
  std::int64_t point = 0;
  double factor = 1.0, height = 0.0, slowedHeight = 0.0;
  bool fits = true;
};

// What slowing down where the axes cannot keep up does to the deposit.
struct SlowdownRecord {
  std::string heightModel;
  std::array<double, 2> window{};  // mm, the tolerated heights
  std::int64_t pointsSlowed = 0, outsideWindow = 0;
  double maxFactor = 0.0;
  std::optional<std::int64_t> maxFactorPoint, maxHeightPoint;
  std::optional<double> maxHeight;  // mm
  std::vector<std::string> columns{"index", "factor", "height_mm", "slowed_height_mm", "fits"};
  std::vector<SlowedPointRecord> points;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("height_model", s.heightModel), io("window_mm", s.window), io("points_slowed", s.pointsSlowed);
    io("outside_window", s.outsideWindow), io("max_factor", s.maxFactor);
    io.nullable("max_factor_point", s.maxFactorPoint), io.nullable("max_height_mm", s.maxHeight);
    io.nullable("max_height_point", s.maxHeightPoint), io("columns", s.columns), io("points", s.points);
  }
};

struct JointSpeedRecord {
  bool withinLimits = true, allowSlowdown = false, ok = true;
  double maxPercent = 0.0;
  std::string axis;
  std::optional<std::int64_t> point;
  std::int64_t pointsOverLimit = 0;
  std::vector<std::int64_t> overLimitIndices;
  std::map<std::string, AxisSpeedRecord> perAxis;
  std::optional<SlowdownRecord> slowdown;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("within_limits", s.withinLimits), io("allow_slowdown", s.allowSlowdown), io("ok", s.ok);
    io("max_percent", s.maxPercent), io("axis", s.axis), io.nullable("point", s.point);
    io("points_over_limit", s.pointsOverLimit), io("over_limit_indices", s.overLimitIndices);
    io("per_axis", s.perAxis), io.optional("slowdown", s.slowdown);
  }
};

struct OptimisationRecord {
  bool enabled = false, optimised = false;
  double objectiveBefore = 0.0, penaltyBefore = 0.0, objectiveAfter = 0.0, penaltyAfter = 0.0;
  std::int64_t layers = 0, posesSolved = 0;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("enabled", s.enabled), io("optimised", s.optimised), io("objective_before", s.objectiveBefore);
    io("penalty_before", s.penaltyBefore), io("objective_after", s.objectiveAfter);
    io("penalty_after", s.penaltyAfter), io("layers", s.layers), io("poses_solved", s.posesSolved);
  }
};

// The kinematics stage: the robot motion on the cell (merged into report.json's top level). The
// index lists hold the first points of each kind.
struct MotionStageReport {
  std::string cell, controller, configuration;
  bool reachable = false;
  std::int64_t unreachablePoints = 0;
  std::vector<std::int64_t> unreachableIndices;
  double minLimitMarginDeg = 0.0;
  std::string minLimitMarginAxis;
  std::optional<std::int64_t> minLimitMarginPoint;
  double minDexterity = 0.0;
  std::optional<std::int64_t> minDexterityPoint;
  double maxJointSpeedRatio = 0.0;
  std::string maxJointSpeedAxis;
  std::optional<std::int64_t> maxJointSpeedPoint;
  JointSpeedRecord jointSpeed;
  std::optional<std::map<std::string, std::array<double, 2>>> positionerRange;  // deg, per axis
  // How far the positioner may leave the build direction off the vertical (deg); with a positioner.
  std::optional<double> positionerToleranceDeg;
  double maxCableTwistDeg = 0.0, cableTwistLimitDeg = 0.0;
  bool withinCableTwistLimit = true;
  std::int64_t collisions = 0, collisionsDetected = 0, collisionsResolved = 0;
  std::vector<std::int64_t> collisionIndices;
  std::int64_t robotCollisions = 0, robotPointsChecked = 0;
  std::vector<std::int64_t> robotCollisionIndices;
  std::vector<std::string> robotCollisionLinks, cellWarnings;
  OptimisationRecord optimisation;
  SecondsPerStep timings;  // torch collisions, joint motion, robot links
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("cell", s.cell), io("controller", s.controller), io("reachable", s.reachable);
    io("unreachable_points", s.unreachablePoints), io("unreachable_indices", s.unreachableIndices);
    io("configuration", s.configuration), io("min_joint_limit_margin_deg", s.minLimitMarginDeg);
    io("min_joint_limit_margin_axis", s.minLimitMarginAxis);
    io.nullable("min_joint_limit_margin_point", s.minLimitMarginPoint), io("min_dexterity", s.minDexterity);
    io.nullable("min_dexterity_point", s.minDexterityPoint),
        io("max_joint_speed_ratio", s.maxJointSpeedRatio);
    io("max_joint_speed_axis", s.maxJointSpeedAxis),
        io.nullable("max_joint_speed_point", s.maxJointSpeedPoint);
    io("joint_speed", s.jointSpeed), io.optional("positioner_range_deg", s.positionerRange);
    io.optional("positioner_tolerance_deg", s.positionerToleranceDeg);
    io("max_cable_twist_deg", s.maxCableTwistDeg), io("cable_twist_limit_deg", s.cableTwistLimitDeg);
    io("within_cable_twist_limit", s.withinCableTwistLimit), io("collisions", s.collisions);
    io("collision_indices", s.collisionIndices), io("collisions_detected", s.collisionsDetected);
    io("collisions_resolved", s.collisionsResolved), io("robot_collisions", s.robotCollisions);
    io("robot_collision_indices", s.robotCollisionIndices),
        io("robot_collision_links", s.robotCollisionLinks);
    io("robot_points_checked", s.robotPointsChecked), io("cell_warnings", s.cellWarnings);
    io("optimisation", s.optimisation), io("kinematics_timings_s", s.timings);
  }
};

// The kinematics stage as the document stores it: the motion and the stage's own wall time, which
// report.json lists under timings_s instead.
struct KinematicsStageReport {
  MotionStageReport motion;
  double seconds = 0.0;
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    MotionStageReport::fields(s.motion, io);
    io("seconds", s.seconds);
  }
};

// The export stage's result: the robot program written from the plan.
struct ExportStageResult {
  std::string exporter;            // plugin id
  std::vector<std::string> files;  // written, in the order written
  template <class S, class Io>
  static void fields(S& s, Io& io)
  {
    io("exporter", s.exporter), io("files", s.files);
  }
};

}  // namespace spira
