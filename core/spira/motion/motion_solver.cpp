#include "spira/motion/motion_solver.h"

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/kinematics/path_tracker.h"
#include "spira/motion/motion_checks.h"
#include "spira/motion/motion_frames.h"
#include "spira/motion/motion_layers.h"
#include "spira/motion/spin_cost.h"
#include "spira/motion/spin_optimiser.h"

namespace spira {

namespace {

struct Plan {
  std::vector<double> spin;  // tool_frame spin per point
  PathTrack track;
  std::vector<SolvedPose> poses;
  double objective = 0.0;
  double penalty = 0.0;
  double cost() const { return objective + penalty; }
};

Plan trackPlan(const ArmIk& ik, const SpinCost& cost, const JointPathSetup& setup, std::vector<double> spin,
               Progress& progress)
{
  Plan plan;
  plan.spin = std::move(spin);
  std::vector<Transform> baseTcp(plan.spin.size());
  for (size_t i = 0; i < baseTcp.size(); ++i) baseTcp[i] = cost.baseTcp(i, plan.spin[i]);
  plan.track = trackPath(ik, baseTcp, setup.flangeTcp, setup.seed, cost.configuration(), progress);
  plan.poses.resize(baseTcp.size());
  for (size_t i = 0; i < baseTcp.size(); ++i) {
    const TrackedPose& t = plan.track.poses[i];
    SolvedPose& p = plan.poses[i];
    p.q = t.q;
    p.reached = t.reachable;
    p.dexterity = t.dexterity;
    p.deg = cost.convention().toControllerDeg(t.q);
    if (i > 0) plan.objective += cost.objective(plan.poses[i - 1], p);
    plan.penalty += cost.penalty(p);
  }
  return plan;
}

JointTrajectory jointTrajectory(const ControllerConvention& convention, const ArmIk& ik,
                                const JointPathSetup& setup, const MotionFrames& frames, const Plan& plan,
                                std::vector<bool>& reached)
{
  JointTrajectory out;
  out.controller = convention.id();
  out.cellName = setup.cellName;
  out.flangeTcp = setup.flangeTcp;
  out.hasPositioner = setup.positioner != nullptr;
  out.robotLimits = convention.axisLimits();
  if (setup.positioner)
    for (size_t k = 0; k < 2; ++k) {
      const ChainJoint& j = setup.positioner->chain().joint(k);
      out.externalLimits[k] = {"E" + std::to_string(k + 1), radToDeg(j.lower), radToDeg(j.upper),
                               radToDeg(j.maxVelocity)};
    }
  const size_t n = plan.poses.size();
  out.points.resize(n);
  reached.assign(n, false);
  for (size_t i = 0; i < n; ++i) {
    JointPoint& p = out.points[i];
    const SolvedPose& pose = plan.poses[i];
    convention.describe(ik.model(), pose.q, p);
    p.externalDeg = {radToDeg(frames.external[i][0]), radToDeg(frames.external[i][1])};
    p.baseTcp = frames.baseTcp0[i] * spinAboutTorch(plan.spin[i]);
    reached[i] = pose.reached && frames.positionerReached[i];
    bool inside = convention.limitMargin(pose.q) >= 0.0;
    if (setup.positioner) inside = inside && setup.positioner->limitMargin(frames.external[i]) >= 0.0;
    p.reachable = reached[i] && inside;
    p.dexterity = pose.dexterity;
  }
  return out;
}

}  // namespace

MotionResult solveMotion(const ArmIk& ik, const ControllerConvention& convention, const Trajectory& path,
                         const JointPathSetup& setup, const MotionParams& params, Progress& progress)
{
  params.validate();
  if (path.empty())
    throw InputError("the path to solve the robot motion for has no points", "plan a trajectory first");
  if (!setup.seed.allFinite() || !std::isfinite(setup.spinRad))
    throw InputError("the motion setup's seed joints or spin are not finite", "check the cell's start pose");

  SubProgress framesProgress(progress, 0.0, 0.02, "placing the path");
  const MotionFrames frames = buildMotionFrames(path, setup, params, framesProgress);
  const ArmConfiguration configuration =
      setup.configuration ? *setup.configuration : ik.configurationOf(setup.seed);
  const SpinCost cost(ik, convention, frames, setup.flangeTcp, configuration, params);
  const size_t n = path.size();

  // The constant chart value that gives setup.spinRad at the first point.
  const double constantChart = setup.spinRad - frames.chartOffset[0];
  std::vector<double> constantSpin(n, setup.spinRad);
  if (params.constantSpin == ConstantSpin::InRobotFrame)
    for (size_t i = 0; i < n; ++i) constantSpin[i] = frames.chartOffset[i] + constantChart;
  const double constantEnd = params.optimiseSpin ? 0.1 : 0.98;
  SubProgress constantProgress(progress, 0.02, constantEnd, "constant spin");
  Plan constant = trackPlan(ik, cost, setup, constantSpin, constantProgress);

  const std::vector<MotionLayer> layers = splitLayers(path, params);
  std::vector<LayerSpinSolution> solutions;
  Plan result;
  bool optimised = false;
  if (params.optimiseSpin) {
    const SpinOptimiser optimiser(cost, params);
    SubProgress optimiserProgress(progress, 0.1, 0.9, "spin optimisation");
    solutions = optimiser.optimisePath(layers, setup.seed, constantChart, optimiserProgress);
    const std::vector<double> chart = SpinOptimiser::chartSpins(layers, solutions);
    std::vector<double> spin(n);
    for (size_t i = 0; i < n; ++i) spin[i] = frames.chartOffset[i] + chart[i];
    SubProgress finalProgress(progress, 0.9, 0.98, "optimised spin");
    result = trackPlan(ik, cost, setup, spin, finalProgress);
    optimised = result.cost() <= constant.cost();
  }
  const Plan& chosen = optimised ? result : constant;

  MotionResult out;
  std::vector<bool> reached;
  out.joints = jointTrajectory(convention, ik, setup, frames, chosen, reached);
  out.spinRad = chosen.spin;
  MotionReport& report = out.report;
  checkMotion(path, out.joints, reached, params.cableTwistLimitDeg, report);
  report.objectiveConstant = constant.objective;
  report.penaltyConstant = constant.penalty;
  report.objectiveResult = chosen.objective;
  report.penaltyResult = chosen.penalty;
  report.optimised = optimised;
  for (const LayerSpinSolution& s : solutions) report.posesSolved += s.evaluations;
  for (size_t k = 0; k < layers.size(); ++k) {
    const MotionLayer& layer = layers[k];
    LayerSpin ls;
    ls.path = layer.path;
    ls.revolution = layer.revolution;
    ls.firstPoint = layer.first;
    ls.pointCount = layer.count;
    ls.startSpinRad = chosen.spin[layer.first];
    ls.endSpinRad = chosen.spin[layer.first + layer.count - 1];
    const size_t end = layer.first + layer.count + (layer.hasNext ? 1 : 0);
    for (size_t i = layer.first + 1; i < end; ++i)
      ls.objective += cost.objective(chosen.poses[i - 1], chosen.poses[i]);
    if (optimised) {
      ls.coefficients = solutions[k].coefficients;
      ls.polished = solutions[k].polished;
    } else if (params.constantSpin == ConstantSpin::InRobotFrame) {
      ls.coefficients = {constantChart};
    }
    report.layers.push_back(std::move(ls));
  }
  progress.report(1.0, "robot motion");
  return out;
}

}  // namespace spira
