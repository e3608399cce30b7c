#include "spira/pipeline/plan_motion.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "spira/base/units.h"
#include "spira/collision/collision_resolver.h"
#include "spira/motion/motion_solver.h"
#include "spira/path/tool_tilt.h"
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

std::vector<std::int64_t> firstIndices(const std::vector<size_t>& indices)
{
  std::vector<std::int64_t> a;
  for (size_t k = 0; k < std::min(indices.size(), kListedIndices); ++k)
    a.push_back(static_cast<std::int64_t>(indices[k]));
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
  // A substrate mesh (a pipe, a scanned plate) is carried with the part: the arm is checked against both.
  TriangleMesh obstacles;
  const TriangleMesh* carried = settings.part;
  if (settings.substrate && !settings.substrate->isPlane()) {
    obstacles = *settings.part;
    const TriangleMesh& substrate = *settings.substrate->surfaceMesh();
    const int offset = static_cast<int>(obstacles.vertices.size());
    obstacles.vertices.insert(obstacles.vertices.end(), substrate.vertices.begin(), substrate.vertices.end());
    for (const Face& f : substrate.faces)
      obstacles.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
    carried = &obstacles;
  }
  const RobotCollisionModel model(cell, *carried, Vec3(600, 600, 20), settings.substrateZ);
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

std::optional<std::int64_t> indexOrNone(size_t i)
{
  if (i == MotionReport::kNone) return std::nullopt;
  return static_cast<std::int64_t>(i);
}

SlowdownRecord slowdownRecord(const SlowdownReport& s, const DepositWindow& window)
{
  SlowdownRecord r;
  r.heightModel = s.model;
  r.window = {window.hMin - window.tolerance, window.hMax + window.tolerance};
  r.pointsSlowed = static_cast<std::int64_t>(s.points.size());
  r.outsideWindow = static_cast<std::int64_t>(s.outsideWindow);
  r.maxFactor = s.maxFactor;
  if (!s.points.empty()) {
    r.maxFactorPoint = static_cast<std::int64_t>(s.maxFactorPoint);
    r.maxHeight = s.maxSlowedHeight;
    r.maxHeightPoint = static_cast<std::int64_t>(s.maxSlowedHeightPoint);
  }
  for (const SlowedPoint& p : s.points)
    r.points.push_back(
        {static_cast<std::int64_t>(p.point), p.factor, p.plannedHeight, p.slowedHeight, p.fits});
  return r;
}

// Each positioner axis's [min, max] over the path: the rotary axis's winding (positioner_path.h).
std::map<std::string, std::array<double, 2>> positionerRange(const JointTrajectory& joints)
{
  std::map<std::string, std::array<double, 2>> out;
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
JointSpeedRecord jointSpeedRecord(const MotionReport& m, const PlanMotion& out,
                                  const MotionSettings& settings)
{
  std::vector<size_t> over;
  for (size_t i = 0; i < m.speedRatio.size(); ++i)
    if (m.speedRatio[i] > 1.0) over.push_back(i);
  JointSpeedRecord j;
  for (const MotionReport::AxisSpeed& a : m.axisSpeeds)
    j.perAxis[a.axis] = {100.0 * a.maxRatio, indexOrNone(a.point)};
  j.withinLimits = over.empty();
  j.allowSlowdown = settings.process.allowSlowdown;
  j.ok = out.withinJointSpeeds;
  j.maxPercent = 100.0 * m.maxSpeedRatio;
  j.axis = m.maxSpeedRatioAxis;
  j.point = indexOrNone(m.maxSpeedRatioPoint);
  j.pointsOverLimit = static_cast<std::int64_t>(over.size());
  j.overLimitIndices = firstIndices(over);
  if (settings.process.allowSlowdown) j.slowdown = slowdownRecord(out.slowdown, settings.window);
  return j;
}

}  // namespace

MotionParams motionParamsFor(const RobotCell& cell, const MotionSettings& settings)
{
  MotionParams p;
  p.optimiseSpin = settings.optimiseSpin;
  p.buildTiltToleranceDeg = radToDeg(settings.process.positionerTiltTolerance);
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

PlanMotion solvePlanMotion(const RobotCell& cell, const Trajectory& planned, const MotionSettings& settings,
                           Progress& progress)
{
  PlanMotion out;
  // The torch's own angles come first: collisions are checked, and resolved, on the torch as held.
  const TorchTilt torch{settings.process.torchLead, settings.process.torchSide};
  const Trajectory tilted = torch.any() ? withTorchTilt(planned, torch) : Trajectory{};
  const Trajectory& plan = torch.any() ? tilted : planned;
  DepositParams deposit;
  deposit.beadWidth = settings.beadWidth;
  CollisionScene scene;
  if (settings.substrate && !settings.substrate->isPlane())
    scene.setSubstrateMesh(*settings.substrate->surfaceMesh());
  else
    scene.setSubstratePlane(Vec3(0, 0, settings.substrateZ), Vec3::UnitZ());
  const TorchCollisionChecker checker(plan, torchOf(cell.record().tool), deposit, std::move(scene));
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point from) {
    return std::chrono::duration<double>(Clock::now() - from).count();
  };
  auto lap = Clock::now();
  SecondsPerStep timings;
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

  MotionStageReport& r = out.report;
  r.cell = cell.record().name;
  r.controller = out.joints.controller;
  r.reachable = out.reachable;
  r.unreachablePoints = static_cast<std::int64_t>(unreachable.size());
  r.unreachableIndices = firstIndices(unreachable);
  // One label per sub-path, in build order (one for a single spiral).
  for (size_t k = 0; k < setups.size(); ++k)
    r.configuration +=
        (k ? ", " : "") + (setups[k].configuration ? setups[k].configuration->label() : std::string());
  r.minLimitMarginDeg = std::isfinite(m.minLimitMarginDeg) ? m.minLimitMarginDeg : 0.0;
  r.minLimitMarginAxis = m.minLimitMarginAxis;
  r.minLimitMarginPoint = indexOrNone(m.minLimitMarginPoint);
  r.minDexterity = m.minDexterity;
  r.minDexterityPoint = indexOrNone(m.minDexterityPoint);
  r.maxJointSpeedRatio = m.maxSpeedRatio;
  r.maxJointSpeedAxis = m.maxSpeedRatioAxis;
  r.maxJointSpeedPoint = indexOrNone(m.maxSpeedRatioPoint);
  r.jointSpeed = jointSpeedRecord(m, out, settings);
  if (out.joints.hasPositioner) {
    r.positionerRange = positionerRange(out.joints);
    r.positionerToleranceDeg = radToDeg(settings.process.positionerTiltTolerance);
  }
  r.maxCableTwistDeg = m.maxCableTwistDeg;
  r.cableTwistLimitDeg = cell.record().cableTwistLimitDeg;
  r.withinCableTwistLimit = m.withinCableTwistLimit;
  r.collisions = static_cast<std::int64_t>(unresolved.size());
  r.collisionIndices = firstIndices(unresolved);
  r.collisionsDetected = static_cast<std::int64_t>(colliding.size());
  r.collisionsResolved =
      settings.resolveCollisions ? static_cast<std::int64_t>(colliding.size() - unresolved.size()) : 0;
  r.robotCollisions = static_cast<std::int64_t>(links.points.size());
  r.robotCollisionIndices = firstIndices(links.points);
  r.robotCollisionLinks = links.links;
  r.robotPointsChecked = static_cast<std::int64_t>(links.checked);
  r.cellWarnings = links.warnings;
  r.optimisation = {settings.optimiseSpin,
                    m.optimised,
                    m.objectiveConstant,
                    m.penaltyConstant,
                    m.objectiveResult,
                    m.penaltyResult,
                    static_cast<std::int64_t>(m.layers.size()),
                    static_cast<std::int64_t>(m.posesSolved)};
  r.timings = timings;
  return out;
}

}  // namespace spira
