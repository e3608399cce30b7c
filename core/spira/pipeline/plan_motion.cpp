#include "spira/pipeline/plan_motion.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "spira/base/units.h"
#include "spira/collision/collision_resolver.h"
#include "spira/motion/motion_solver.h"
#include "spira/pipeline/sub_paths.h"
#include "spira/planning/plan_schemas.h"
#include "spira/robotcell/robot_collision_model.h"

namespace spira {
namespace {

constexpr size_t kListedIndices = 50;  // the report lists the first offending points

TorchParams torchOf(const ToolRecord& tool)
{
  TorchParams t;
  t.nozzleRadius = tool.nozzleRadius;
  t.coneLength = tool.nozzleLength;
  t.bodyRadius = tool.torchBodyRadius;
  t.bodyLength = tool.torchBodyLength;
  return t;
}

nlohmann::json firstIndices(const std::vector<size_t>& indices)
{
  nlohmann::json a = nlohmann::json::array();
  for (size_t k = 0; k < std::min(indices.size(), kListedIndices); ++k) a.push_back(indices[k]);
  return a;
}

struct LinkCheck {
  std::vector<size_t> points;  // checked points where a link hits
  std::vector<std::string> links;
  size_t checked = 0;
  std::vector<std::string> warnings;
};

LinkCheck checkRobotLinks(const RobotCell& cell, const JointPathSetup& setup, const Trajectory& path,
                          const JointTrajectory& joints, const MotionSettings& settings, Progress& progress)
{
  LinkCheck out;
  const RobotCollisionModel model(cell, *settings.part, Vec3(600, 600, 20), settings.substrateZ);
  out.warnings = model.warnings();
  double since = settings.linkCheckSpacing;
  for (size_t i = 0; i < path.size(); ++i) {
    if (i > 0) since += (path.points[i].position - path.points[i - 1].position).norm();
    if (since < settings.linkCheckSpacing && i + 1 < path.size()) continue;
    since = 0.0;
    if ((out.checked & 63) == 0) progress.checkCancel();
    ++out.checked;
    const JointPoint& j = joints.points[i];
    const JointVector q = cell.convention().fromControllerDeg(j.robotDeg);
    const Eigen::Vector2d e(degToRad(j.externalDeg[0]), degToRad(j.externalDeg[1]));
    const Transform basePart = setup.positioner
                                   ? setup.basePositioner * setup.positioner->forward(e) * setup.tablePart
                                   : setup.basePart;
    const auto hits = model.armHits(q, basePart, e);
    if (hits.empty()) continue;
    out.points.push_back(i);
    for (const auto& h : hits)
      if (std::find(out.links.begin(), out.links.end(), h) == out.links.end()) out.links.push_back(h);
  }
  return out;
}

nlohmann::json indexOrNull(size_t i)
{
  return i == MotionReport::kNone ? nlohmann::json(nullptr) : nlohmann::json(i);
}

// A number, or null where it is not finite (a turn on the spot needs an infinite speed).
nlohmann::json finiteOrNull(double v)
{
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json slowdownJson(const SlowdownReport& s, const DepositWindow& window)
{
  nlohmann::json points = nlohmann::json::array();
  for (const SlowedPoint& p : s.points)
    points.push_back(
        {p.point, finiteOrNull(p.factor), p.plannedHeight, finiteOrNull(p.slowedHeight), p.fits});
  return {{"height_model", s.model},
          {"window_mm", {window.hMin - window.tolerance, window.hMax + window.tolerance}},
          {"points_slowed", s.points.size()},
          {"outside_window", s.outsideWindow},
          {"max_factor", finiteOrNull(s.maxFactor)},
          {"max_factor_point", s.points.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.maxFactorPoint)},
          {"max_height_mm", s.points.empty() ? nlohmann::json(nullptr) : finiteOrNull(s.maxSlowedHeight)},
          {"max_height_point",
           s.points.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.maxSlowedHeightPoint)},
          {"columns", {"index", "factor", "height_mm", "slowed_height_mm", "fits"}},
          {"points", points}};
}

// Each positioner axis's [min, max] over the path: the rotary axis's winding (positioner_path.h).
nlohmann::json positionerRangeJson(const JointTrajectory& joints)
{
  nlohmann::json out = nlohmann::json::object();
  for (size_t k = 0; k < 2; ++k) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const JointPoint& p : joints.points) {
      lo = std::min(lo, p.externalDeg[k]);
      hi = std::max(hi, p.externalDeg[k]);
    }
    if (lo <= hi) out[joints.externalLimits[k].name] = {lo, hi};
  }
  return out;
}

// Which axes pass their speed limit, where and by how much, and what slowing down would do.
nlohmann::json jointSpeedJson(const MotionReport& m, const PlanMotion& out, const MotionSettings& settings)
{
  std::vector<size_t> over;
  for (size_t i = 0; i < m.speedRatio.size(); ++i)
    if (m.speedRatio[i] > 1.0) over.push_back(i);
  nlohmann::json axes = nlohmann::json::object();
  for (const MotionReport::AxisSpeed& a : m.axisSpeeds)
    axes[a.axis] = {{"max_percent", finiteOrNull(100.0 * a.maxRatio)}, {"point", indexOrNull(a.point)}};
  nlohmann::json j = {{"within_limits", over.empty()},
                      {"allow_slowdown", settings.process.allowSlowdown},
                      {"ok", out.withinJointSpeeds},
                      {"max_percent", finiteOrNull(100.0 * m.maxSpeedRatio)},
                      {"axis", m.maxSpeedRatioAxis},
                      {"point", indexOrNull(m.maxSpeedRatioPoint)},
                      {"points_over_limit", over.size()},
                      {"over_limit_indices", firstIndices(over)},
                      {"per_axis", axes}};
  if (settings.process.allowSlowdown) j["slowdown"] = slowdownJson(out.slowdown, settings.window);
  return j;
}

}  // namespace

MotionParams motionParamsFor(const RobotCell& cell, const MotionSettings& settings)
{
  MotionParams p;
  p.optimiseSpin = settings.optimiseSpin;
  p.cableTwistLimitDeg = cell.record().cableTwistLimitDeg;
  return p;
}

MotionSettings motionSettingsFrom(const PlanSections& sections)
{
  MotionSettings m;
  m.process = sections.process;
  m.beadWidth = m.process.beadWidth;
  const SpiralSettings& s = sections.spiral;
  m.window = DepositWindow{s.hMin, s.hMax, s.heightTolerance * s.h};
  return m;
}

PlanMotion solvePlanMotion(const RobotCell& cell, const Trajectory& plan, const MotionSettings& settings,
                           Progress& progress)
{
  PlanMotion out;
  DepositParams deposit;
  deposit.beadWidth = settings.beadWidth;
  CollisionScene scene;
  scene.setSubstratePlane(Vec3(0, 0, settings.substrateZ), Vec3::UnitZ());
  const TorchCollisionChecker checker(plan, torchOf(cell.record().tool), deposit, std::move(scene));
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point from) {
    return std::chrono::duration<double>(Clock::now() - from).count();
  };
  auto lap = Clock::now();
  nlohmann::json timings;
  SubProgress collisionProgress(progress, 0.0, 0.4, "torch collisions");
  CollisionResolution resolution =
      resolveTorchCollisions(plan, checker, ResolveSettings{}, collisionProgress);
  std::vector<size_t> colliding;
  for (size_t i = 0; i < resolution.hits.size(); ++i)
    if (resolution.hits[i]) colliding.push_back(i);
  const std::vector<size_t>& unresolved = settings.resolveCollisions ? resolution.unresolved : colliding;
  out.unresolvedCollisions = unresolved.size();
  out.trajectory = settings.resolveCollisions ? std::move(resolution.trajectory) : plan;

  timings["torch_collisions"] = seconds(lap);
  lap = Clock::now();
  SubProgress ikProgress(progress, 0.4, 0.8, "joint motion");
  // One solve per sub-path (a multi-branch plan): each holds its own arm configuration.
  std::vector<JointPathSetup> setups;
  MotionResult solved =
      solveSubPaths(cell, out.trajectory, motionParamsFor(cell, settings), ikProgress, &setups);
  const JointPathSetup& setup = setups.front();
  out.joints = std::move(solved.joints);
  const MotionReport& m = solved.report;
  for (size_t i : unresolved) out.joints.points[i].collision = true;
  timings["joint_motion"] = seconds(lap);
  lap = Clock::now();
  LinkCheck links;
  if (settings.part) {
    SubProgress linkProgress(progress, 0.8, 1.0, "robot links");
    links = checkRobotLinks(cell, setup, out.trajectory, out.joints, settings, linkProgress);
    for (size_t i : links.points) out.joints.points[i].collision = true;
    out.robotCollisions = links.points.size();
  }
  timings["robot_links"] = seconds(lap);

  std::vector<size_t> unreachable = m.unreachable;
  unreachable.insert(unreachable.end(), m.outsideLimits.begin(), m.outsideLimits.end());
  std::sort(unreachable.begin(), unreachable.end());
  out.reachable = m.reachable && unreachable.empty() && m.withinCableTwistLimit;
  // The controller cannot run an axis past its speed limit: it stops with an error, or, when
  // allowed, slows the move down, which thickens the deposit.
  if (settings.process.allowSlowdown)
    out.slowdown = slowdownDeposit(out.trajectory, m.speedRatio, settings.process, settings.window);
  out.withinJointSpeeds = m.maxSpeedRatio <= 1.0 || (settings.process.allowSlowdown && out.slowdown.fits());

  nlohmann::json& r = out.report;
  r["cell"] = cell.record().name;
  r["controller"] = out.joints.controller;
  r["reachable"] = out.reachable;
  r["unreachable_points"] = unreachable.size();
  r["unreachable_indices"] = firstIndices(unreachable);
  // One label per sub-path, in build order (one for a single spiral).
  std::string configurations;
  for (size_t k = 0; k < setups.size(); ++k)
    configurations +=
        (k ? ", " : "") + (setups[k].configuration ? setups[k].configuration->label() : std::string());
  r["configuration"] = configurations;
  r["min_joint_limit_margin_deg"] = std::isfinite(m.minLimitMarginDeg) ? m.minLimitMarginDeg : 0.0;
  r["min_joint_limit_margin_axis"] = m.minLimitMarginAxis;
  r["min_joint_limit_margin_point"] = indexOrNull(m.minLimitMarginPoint);
  r["min_dexterity"] = m.minDexterity;
  r["min_dexterity_point"] = indexOrNull(m.minDexterityPoint);
  r["max_joint_speed_ratio"] = m.maxSpeedRatio;
  r["max_joint_speed_axis"] = m.maxSpeedRatioAxis;
  r["max_joint_speed_point"] = indexOrNull(m.maxSpeedRatioPoint);
  r["joint_speed"] = jointSpeedJson(m, out, settings);
  if (out.joints.hasPositioner) r["positioner_range_deg"] = positionerRangeJson(out.joints);
  r["max_cable_twist_deg"] = m.maxCableTwistDeg;
  r["cable_twist_limit_deg"] = cell.record().cableTwistLimitDeg;
  r["within_cable_twist_limit"] = m.withinCableTwistLimit;
  r["collisions"] = unresolved.size();
  r["collision_indices"] = firstIndices(unresolved);
  r["collisions_detected"] = colliding.size();
  r["collisions_resolved"] = settings.resolveCollisions ? colliding.size() - unresolved.size() : 0;
  r["robot_collisions"] = links.points.size();
  r["robot_collision_indices"] = firstIndices(links.points);
  r["robot_collision_links"] = links.links;
  r["robot_points_checked"] = links.checked;
  r["cell_warnings"] = links.warnings;
  r["optimisation"] = {{"enabled", settings.optimiseSpin},
                       {"optimised", m.optimised},
                       {"objective_before", m.objectiveConstant},
                       {"penalty_before", m.penaltyConstant},
                       {"objective_after", m.objectiveResult},
                       {"penalty_after", m.penaltyResult},
                       {"layers", m.layers.size()},
                       {"poses_solved", m.posesSolved}};
  r["kinematics_timings_s"] = timings;
  return out;
}

}  // namespace spira
