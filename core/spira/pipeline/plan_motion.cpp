#include "spira/pipeline/plan_motion.h"

#include <algorithm>
#include <cmath>

#include "spira/base/units.h"
#include "spira/collision/collision_resolver.h"
#include "spira/kinematics/joint_path_solver.h"
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

// Largest |dq| / dt over the axis speed limit, dt = segment length / travel speed of the move.
double maxJointSpeedRatio(const JointTrajectory& joints, const Trajectory& path, std::string& axis)
{
  double worst = 0.0;
  for (size_t i = 1; i < joints.size(); ++i) {
    const double ts = path.points[i].travelSpeed;
    const double len = (path.points[i].position - path.points[i - 1].position).norm();
    if (ts <= 0.0 || len <= 0.0) continue;
    const double dt = len / ts;
    for (size_t k = 0; k < 6; ++k) {
      const double r = std::abs(joints.points[i].robotDeg[k] - joints.points[i - 1].robotDeg[k]) / dt /
                       joints.robotLimits[k].maxSpeedDegPerS;
      if (r > worst) worst = r, axis = joints.robotLimits[k].name;
    }
    for (size_t k = 0; joints.hasPositioner && k < 2; ++k) {
      const double r = std::abs(joints.points[i].externalDeg[k] - joints.points[i - 1].externalDeg[k]) / dt /
                       joints.externalLimits[k].maxSpeedDegPerS;
      if (r > worst) worst = r, axis = joints.externalLimits[k].name;
    }
  }
  return worst;
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

}  // namespace

PlanMotion solvePlanMotion(const RobotCell& cell, const Trajectory& plan, const MotionSettings& settings,
                           Progress& progress)
{
  PlanMotion out;
  DepositParams deposit;
  deposit.beadWidth = settings.beadWidth;
  CollisionScene scene;
  scene.setSubstratePlane(Vec3(0, 0, settings.substrateZ), Vec3::UnitZ());
  const TorchCollisionChecker checker(plan, torchOf(cell.record().tool), deposit, std::move(scene));
  SubProgress collisionProgress(progress, 0.0, 0.4, "torch collisions");
  CollisionResolution resolution =
      resolveTorchCollisions(plan, checker, ResolveSettings{}, collisionProgress);
  std::vector<size_t> colliding;
  for (size_t i = 0; i < resolution.hits.size(); ++i)
    if (resolution.hits[i]) colliding.push_back(i);
  const std::vector<size_t>& unresolved = settings.resolveCollisions ? resolution.unresolved : colliding;
  out.unresolvedCollisions = unresolved.size();
  out.trajectory = settings.resolveCollisions ? std::move(resolution.trajectory) : plan;

  SubProgress ikProgress(progress, 0.4, 0.8, "joint motion");
  const JointPathSetup setup = cell.seededSetup(out.trajectory);
  out.joints = solveJointTrajectory(cell.ik(), cell.convention(), out.trajectory, setup, ikProgress);
  for (size_t i : unresolved) out.joints.points[i].collision = true;
  LinkCheck links;
  if (settings.part) {
    SubProgress linkProgress(progress, 0.8, 1.0, "robot links");
    links = checkRobotLinks(cell, setup, out.trajectory, out.joints, settings, linkProgress);
    for (size_t i : links.points) out.joints.points[i].collision = true;
    out.robotCollisions = links.points.size();
  }

  std::vector<size_t> unreachable;
  double minMargin = std::numeric_limits<double>::infinity(), minDexterity = 1.0, maxTwist = 0.0;
  std::string marginAxis;
  const auto& limits = out.joints.robotLimits;
  for (size_t i = 0; i < out.joints.size(); ++i) {
    const JointPoint& p = out.joints.points[i];
    if (!p.reachable) unreachable.push_back(i);
    for (size_t k = 0; k < 6; ++k) {
      const double m = std::min(p.robotDeg[k] - limits[k].minDeg, limits[k].maxDeg - p.robotDeg[k]);
      if (m < minMargin) minMargin = m, marginAxis = limits[k].name;
    }
    minDexterity = std::min(minDexterity, p.dexterity);
    maxTwist = std::max(maxTwist, std::abs(p.robotDeg[3] + p.robotDeg[5]));
  }
  out.reachable = unreachable.empty();
  std::string speedAxis;
  const double speedRatio = maxJointSpeedRatio(out.joints, out.trajectory, speedAxis);

  nlohmann::json& r = out.report;
  r["cell"] = cell.record().name;
  r["controller"] = out.joints.controller;
  r["reachable"] = out.reachable;
  r["unreachable_points"] = unreachable.size();
  r["unreachable_indices"] = firstIndices(unreachable);
  r["configuration"] = setup.configuration ? setup.configuration->label() : std::string();
  r["min_joint_limit_margin_deg"] = out.joints.size() ? minMargin : 0.0;
  r["min_joint_limit_margin_axis"] = marginAxis;
  r["min_dexterity"] = minDexterity;
  r["max_joint_speed_ratio"] = speedRatio;
  r["max_joint_speed_axis"] = speedAxis;
  r["max_cable_twist_deg"] = maxTwist;
  r["cable_twist_limit_deg"] = cell.record().cableTwistLimitDeg;
  r["collisions"] = unresolved.size();
  r["collision_indices"] = firstIndices(unresolved);
  r["collisions_detected"] = colliding.size();
  r["collisions_resolved"] = settings.resolveCollisions ? colliding.size() - unresolved.size() : 0;
  r["robot_collisions"] = links.points.size();
  r["robot_collision_indices"] = firstIndices(links.points);
  r["robot_collision_links"] = links.links;
  r["robot_points_checked"] = links.checked;
  r["cell_warnings"] = links.warnings;
  r["optimisation"] = {
      {"mode", "constant_spin"}, {"objective_before", nullptr}, {"objective_after", nullptr}};
  return out;
}

}  // namespace spira
