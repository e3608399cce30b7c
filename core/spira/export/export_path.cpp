#include "spira/export/export_path.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/export/fixed_number.h"
#include "spira/path/dwell.h"
#include "spira/path/tool_frame.h"

namespace spira {

namespace {

// A move never gets a slower commanded speed than this (mm/s): a positioner turning under a
// nearly still torch would otherwise ask for a zero speed, which controllers refuse.
constexpr double kMinSpeed = 0.01;

std::string pointText(size_t i)
{
  return "point " + std::to_string(i);
}

bool finite(const Vec3& v)
{
  return v.allFinite();
}

bool namedLimit(const AxisLimit& limit)
{
  return !limit.name.empty();
}

void checkChannels(const TrajectoryPoint& p, size_t i)
{
  if (!finite(p.position) || !finite(p.build) || !finite(p.tangent) || !finite(p.normal))
    throw InputError("the plan's " + pointText(i) + " has a non-finite position or direction",
                     "plan the part again");
  if (!(p.travelSpeed > 0.0) || !std::isfinite(p.travelSpeed))
    throw InputError("the plan's " + pointText(i) + " has travel speed " + roundedText(p.travelSpeed, 3) +
                         " mm/s; every point needs a positive speed",
                     "check the process settings (travel speed) and plan again");
  if (!(p.wireFeed >= 0.0) || !std::isfinite(p.wireFeed))
    throw InputError("the plan's " + pointText(i) + " has wire feed " + roundedText(p.wireFeed, 3) + " mm/s",
                     "check the process settings (wire feed) and plan again");
}

std::string limitProblems(const JointPoint& jp, const JointTrajectory& joints)
{
  std::string out;
  auto check = [&out](const AxisLimit& limit, double value) {
    if (!namedLimit(limit)) return;
    if (value < limit.minDeg - 1e-9 || value > limit.maxDeg + 1e-9) {
      if (!out.empty()) out += ", ";
      out += limit.name + " outside its limits";
    }
  };
  for (size_t k = 0; k < 6; ++k) check(joints.robotLimits[k], jp.robotDeg[k]);
  if (joints.hasPositioner)
    for (size_t k = 0; k < 2; ++k) check(joints.externalLimits[k], jp.externalDeg[k]);
  return out;
}

std::string pointProblem(const JointPoint& jp, const JointTrajectory& joints)
{
  std::string out;
  if (!jp.reachable) out = "unreachable";
  if (jp.collision) out += std::string(out.empty() ? "" : ", ") + "in collision";
  const std::string limits = limitProblems(jp, joints);
  if (!limits.empty()) out += std::string(out.empty() ? "" : ", ") + limits;
  return out;
}

// First letters of a FANUC configuration ("N U T" of "N U T, 0, 0, 0"): the arm's branch.
std::string fanucBranch(const std::string& config)
{
  return config.substr(0, config.find(','));
}

struct JointSpeedCheck {
  size_t count = 0;
  std::string first;
  void note(const AxisLimit& limit, double rate, size_t point)
  {
    if (!namedLimit(limit) || !(limit.maxSpeedDegPerS > 0.0) || rate <= limit.maxSpeedDegPerS * (1.0 + 1e-9))
      return;
    if (count++ == 0)
      first = limit.name + " at " + roundedText(std::ceil(rate), 3) + " deg/s into " + pointText(point) +
              ", limit " + roundedText(limit.maxSpeedDegPerS, 3) + " deg/s";
  }
};

void checkJointMotion(const JointTrajectory& joints, ExportPath& path)
{
  JointSpeedCheck speeds;
  size_t branchChanges = 0, firstChange = 0;
  const bool kuka = joints.controller == "kuka_krc4";
  const bool abb = joints.controller == "abb_irc5";
  for (size_t i = 1; i < path.points.size(); ++i) {
    const ExportPoint& a = path.points[i - 1];
    const ExportPoint& b = path.points[i];
    if (b.transfer) continue;  // a joint move: the controller times it and may change configuration
    if (b.moveTime > 0.0) {
      for (size_t k = 0; k < 6; ++k)
        speeds.note(joints.robotLimits[k], std::abs(b.robotDeg[k] - a.robotDeg[k]) / b.moveTime, i);
      if (joints.hasPositioner)
        for (size_t k = 0; k < 2; ++k)
          speeds.note(joints.externalLimits[k], std::abs(b.externalDeg[k] - a.externalDeg[k]) / b.moveTime,
                      i);
    }
    const bool changed = kuka  ? a.kukaStatus != b.kukaStatus
                         : abb ? a.abbConf[3] != b.abbConf[3]
                               : fanucBranch(a.fanucConfig) != fanucBranch(b.fanucConfig);
    if (changed && branchChanges++ == 0) firstChange = i;
  }
  if (speeds.count > 0)
    path.warnings.push_back(std::to_string(speeds.count) +
                            " moves need an axis faster than its limit (first: " + speeds.first +
                            "); the controller will slow down there and the deposit will thicken");
  if (branchChanges > 0)
    path.warnings.push_back("the robot configuration (" +
                            std::string(kuka  ? "KUKA status S"
                                        : abb ? "ABB cfx"
                                              : "FANUC CONFIG") +
                            ") changes " + std::to_string(branchChanges) + " times (first into " +
                            pointText(firstChange) +
                            "); a linear move cannot switch branches, check the kinematics solution");
}

// One arc per run of a sub-path between waits, from its first to its last arc-on point.
void findArcs(const Trajectory& trajectory, ExportPath& path)
{
  const auto& pts = trajectory.points;
  const size_t n = pts.size();
  size_t gaps = 0, firstGap = 0, runStart = 0;
  for (size_t i = 0; i < n; ++i) path.points[i].path = pts[i].path;
  for (size_t i = 1; i <= n; ++i) {
    const bool newPath = i < n && pts[i].path != pts[runStart].path;
    if (i < n && !newPath && path.points[i].dwell <= 0.0) continue;
    size_t first = runStart, last = i;
    while (first < i && !pts[first].arcOn) ++first;
    while (last > first && !pts[last - 1].arcOn) --last;
    if (last > first + 1) {
      --last;
      path.points[first].strike = true;
      path.points[last].stop = true;
      for (size_t k = first; k <= last; ++k) {
        path.points[k].inArc = true;
        if (!pts[k].arcOn && gaps++ == 0) firstGap = k;
      }
      if (path.arcCount++ == 0) path.arcStart = first;
      path.arcEnd = last;
    }
    if (newPath) path.points[i].transfer = true;
    runStart = i;
  }
  if (path.arcCount == 0)
    throw InputError("the plan deposits nothing: the arc is on at fewer than two points",
                     "check the plan's arc channel and plan again");
  if (gaps > 0)
    path.warnings.push_back("the plan switches the arc off at " + std::to_string(gaps) +
                            (gaps == 1 ? " point" : " points") + " inside a sub-path's deposition (first: " +
                            pointText(firstGap) + "); the program keeps one arc per sub-path");
}

// Which moves write a WFS setpoint: only while the arc burns, each arc starting with its own value.
// Without a lead the setpoint of point k is written as move k starts, so moves into points
// strike+1 .. stop; with one, the setpoints of points strike .. stop are written ahead of them.
void markAnalogSetpoints(const PathOptions& options, ExportPath& path)
{
  if (options.process == ProcessCommand::Speed) return;
  double last = 0.0;
  bool any = false;
  for (size_t i = 0; i < path.points.size(); ++i) {
    ExportPoint& p = path.points[i];
    if (p.strike) any = false;
    const bool writable = path.hasLead ? p.inArc : p.inArc && !p.strike;
    if (!writable) continue;
    const double change = std::abs(p.wfs - last);
    if (!any || (options.wfsDeadband > 0.0 ? change >= options.wfsDeadband : change > 1e-12)) {
      p.writeWfs = true;
      last = p.wfs;
      any = true;
    }
  }
}

void refuseOrFlag(const PathOptions& options, ExportPath& path)
{
  std::string listed;
  size_t shown = 0;
  for (size_t i = 0; i < path.points.size(); ++i) {
    if (path.points[i].problem.empty()) continue;
    ++path.flaggedCount;
    if (shown < 5) {
      listed += std::string(shown ? "; " : "") + pointText(i) + " " + path.points[i].problem;
      ++shown;
    }
  }
  if (path.flaggedCount == 0) return;
  const std::string what = std::to_string(path.flaggedCount) + " of " + std::to_string(path.points.size()) +
                           " points cannot be executed as planned (" + listed +
                           (path.flaggedCount > shown ? "; ..." : "") + ")";
  // The plan and its inputs are valid; the cell just cannot execute it: infeasible, not bad input.
  if (!options.force)
    throw InfeasibleError(what,
                          "fix the cell or the plan, or set 'force' to export anyway with a warning "
                          "comment at each of these moves");
  path.warnings.push_back("forced export: " + what + "; each such move carries a warning comment");
}

}  // namespace

ExportPath prepareExportPath(const ExportInput& input, const PathOptions& options, Progress& progress)
{
  const Trajectory& trajectory = input.trajectory;
  const size_t n = trajectory.size();
  if (n < 2)
    throw InputError("the plan has " + std::to_string(n) + " point(s); a program needs at least two",
                     "plan the part before exporting");
  const JointTrajectory* joints = input.joints;
  if (joints) {
    if (joints->controller != options.controller)
      throw InputError("the joint trajectory was solved for controller '" + joints->controller + "', not '" +
                           options.controller + "'",
                       "choose the exporter of the cell's controller, or solve the kinematics for this one");
    if (joints->size() != n)
      throw InputError("the joint trajectory has " + std::to_string(joints->size()) +
                           " points for a plan of " + std::to_string(n),
                       "solve the kinematics again after planning");
  }
  ExportPath path;
  path.hasJoints = joints != nullptr;
  path.hasPositioner = joints && joints->hasPositioner;
  path.points.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double wait = dwellAt(trajectory, i);
    if (!(wait >= 0.0) || !std::isfinite(wait))
      throw InputError("the plan's " + pointText(i) + " has dwell " + roundedText(wait, 3) +
                           " s; a dwell is a wait of 0 s or more",
                       "plan the part again");
    if (wait > 0.0 && trajectory.points[i].arcOn)
      throw InputError("the plan's " + pointText(i) + " waits " + roundedText(wait, 3) +
                           " s with the arc on; a program waits only at a dwell's lift, arc off",
                       "export the plan with spira-cli export or the Export dialog, which lay out the lifts");
    path.points[i].dwell = wait;
  }
  findArcs(trajectory, path);
  const auto command = trajectory.extra.find(kWfsCommandChannel);
  const auto lead = trajectory.extra.find(kWfsLeadChannel);
  path.hasLead = command != trajectory.extra.end() && lead != trajectory.extra.end();
  for (size_t i = 0; i < n; ++i) {
    if ((i & 4095) == 0) {
      progress.checkCancel();
      progress.report(0.5 * static_cast<double>(i) / static_cast<double>(n), "checking the path");
    }
    const TrajectoryPoint& tp = trajectory.points[i];
    checkChannels(tp, i);
    ExportPoint& ep = path.points[i];
    ep.wfs = tp.wireFeed;
    if (path.hasLead) {
      ep.wfs = command->second[i];
      ep.wfsLead = lead->second[i];
      if (!std::isfinite(ep.wfs) || !(ep.wfsLead >= 0.0) || !std::isfinite(ep.wfsLead))
        throw InputError("the led wire feed of " + pointText(i) + " is not a finite setpoint and lead",
                         "export again from the plan");
    }
    if (joints) {
      const JointPoint& jp = joints->points[i];
      ep.pose = jp.baseTcp;
      ep.robotDeg = jp.robotDeg;
      ep.externalDeg = jp.externalDeg;
      ep.kukaStatus = jp.kukaStatus;
      ep.kukaTurn = jp.kukaTurn;
      ep.fanucConfig = jp.fanucConfig;
      ep.abbConf = jp.abbConf;
      ep.problem = pointProblem(jp, *joints);
      bool jointsFinite = true;
      for (double q : jp.robotDeg) jointsFinite = jointsFinite && std::isfinite(q);
      for (double q : jp.externalDeg) jointsFinite = jointsFinite && std::isfinite(q);
      if (!jointsFinite || !ep.pose.matrix().allFinite())
        throw InputError("the joint trajectory's " + pointText(i) + " has non-finite values",
                         "solve the kinematics again");
    } else {
      ep.pose = toolFrame(tp);
    }
    if (i > 0) {
      const double partStep = (tp.position - trajectory.points[i - 1].position).norm();
      const double robotStep = (ep.pose.translation() - path.points[i - 1].pose.translation()).norm();
      if (path.points[i - 1].inArc && ep.inArc) path.length += partStep;
      ep.moveTime = partStep / tp.travelSpeed;
      // Keep the planned duration of every move: with a moving part (positioner) the torch
      // covers another distance than the deposit in the same time.
      ep.speed = std::max(ep.moveTime > 0.0 ? robotStep / ep.moveTime : tp.travelSpeed, kMinSpeed);
    } else {
      ep.speed = tp.travelSpeed;
    }
  }
  if (options.process == ProcessCommand::Analog) {
    const double constant = path.points[std::min(path.arcStart + 1, n - 1)].speed;
    double lo = constant, hi = constant;
    for (size_t i = 1; i < n; ++i) {
      if (!path.points[i - 1].inArc || !path.points[i].inArc) continue;  // travel keeps its own speed
      lo = std::min(lo, path.points[i].speed);
      hi = std::max(hi, path.points[i].speed);
      path.points[i].speed = constant;
    }
    if (hi - lo > 1e-6 * hi)
      path.warnings.push_back("the plan's speed varies from " + roundedText(lo, 3) + " to " +
                              roundedText(hi, 3) + " mm/s but the analog process mode writes one speed, " +
                              roundedText(constant, 3) + " mm/s");
  }
  markAnalogSetpoints(options, path);
  if (joints) checkJointMotion(*joints, path);
  refuseOrFlag(options, path);

  const Transform back(Eigen::Translation3d(0.0, 0.0, -options.approachDistance));
  path.hasApproach = options.approachDistance > 0.0;
  path.approach = path.points.front().pose * back;
  path.retract = path.points.back().pose * back;
  progress.report(0.5, "checking the path");
  return path;
}

}  // namespace spira
