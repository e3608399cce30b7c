#include "spira/kinematics/joint_path_solver.h"

#include "spira/base/units.h"
#include "spira/kinematics/path_tracker.h"
#include "spira/path/tool_frame.h"

namespace spira {

JointTrajectory solveJointTrajectory(const ArmIk& ik, const ControllerConvention& convention,
                                     const Trajectory& path, const JointPathSetup& setup, Progress& progress)
{
  const size_t n = path.size();
  std::vector<Transform> baseTcp(n);
  std::vector<Eigen::Vector2d> external(n, Eigen::Vector2d::Zero());
  std::vector<bool> positionerOk(n, true);
  Eigen::Vector2d e = setup.positionerSeed;
  for (size_t i = 0; i < n; ++i) {
    if ((i & 4095) == 0) progress.checkCancel();
    const TrajectoryPoint& point = path.points[i];
    Transform basePart = setup.basePart;
    if (setup.positioner) {
      const Vec3 buildInTable = setup.tablePart.linear() * point.build;
      const std::optional<Eigen::Vector2d> solved = setup.positioner->solve(buildInTable, e);
      positionerOk[i] = solved && setup.positioner->limitMargin(*solved) >= 0.0;
      if (solved) e = *solved;
      external[i] = e;
      basePart = setup.basePositioner * setup.positioner->forward(e) * setup.tablePart;
    }
    baseTcp[i] = basePart * toolFrame(point, setup.spinRad);
  }

  SubProgress ikProgress(progress, 0.0, 1.0, "inverse kinematics");
  const PathTrack track =
      trackPath(ik, baseTcp, setup.flangeTcp, setup.seed, setup.configuration, ikProgress);

  JointTrajectory out;
  out.controller = convention.id();
  out.cellName = setup.cellName;
  out.flangeTcp = setup.flangeTcp;
  out.hasPositioner = setup.positioner != nullptr;
  out.robotLimits = convention.axisLimits();
  if (setup.positioner) {
    for (size_t k = 0; k < 2; ++k) {
      const ChainJoint& j = setup.positioner->chain().joint(k);
      out.externalLimits[k] = {"E" + std::to_string(k + 1), radToDeg(j.lower), radToDeg(j.upper),
                               radToDeg(j.maxVelocity)};
    }
  }
  out.points.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const TrackedPose& pose = track.poses[i];
    JointPoint& p = out.points[i];
    convention.describe(ik.model(), pose.q, p);
    p.externalDeg = {radToDeg(external[i][0]), radToDeg(external[i][1])};
    p.baseTcp = baseTcp[i];
    p.reachable = pose.reachable && positionerOk[i] && convention.limitMargin(pose.q) >= 0.0;
    p.dexterity = pose.dexterity;
  }
  return out;
}

}  // namespace spira
