#include "spira/pipeline/export_job.h"

#include <chrono>

#include "spira/base/error.h"

#include "spira/motion/motion_solver.h"
#include "spira/pipeline/plan_motion.h"

namespace spira {

ExportOutcome exportTrajectory(const PluginRegistry& registry, const Trajectory& planned,
                               const ExportJob& job, const std::filesystem::path& outDir, Progress& progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  const ExporterPlugin& exporter = registry.exporter(job.exporterId);
  const ParamSet params = job.exporterParams.withDefaults(exporter.schema());
  exporter.schema().validate(params);

  for (const TrajectoryPoint& p : planned.points)
    if (p.path != planned.points.front().path)
      throw InputError(
          "this plan has several sub-paths (a multi-branch part); a robot program with one arc "
          "start and stop per sub-path and travel moves between them is not written yet",
          "export each branch as its own part, or plan a mono-branch part");
  ExportOutcome out;
  SubProgress prepProgress(progress, 0.0, 0.4, "path preparation");
  const PreparedTrajectory prepared = prepareTrajectory(planned, job.prep, prepProgress);
  out.prep = prepared.report;
  out.robotTargets = prepared.trajectory.size();

  JointTrajectory joints;
  if (job.cell) {
    SubProgress ikProgress(progress, 0.4, 0.7, "robot targets");
    const JointPathSetup setup = job.cell->seededSetup(prepared.trajectory);
    // The prepared points are solved (and their spin optimised) afresh: fewer points than the plan,
    // so the program's joints are exactly those of its own targets.
    MotionSettings ms;
    ms.optimiseSpin = job.optimiseSpin;
    joints = solveMotion(job.cell->ik(), job.cell->convention(), prepared.trajectory, setup,
                         motionParamsFor(*job.cell, ms), ikProgress)
                 .joints;
    for (const JointPoint& p : joints.points) out.unreachableTargets += !p.reachable;
  }
  SubProgress writeProgress(progress, 0.7, 1.0, "writing the program");
  const ExportInput input{prepared.trajectory, job.cell ? &joints : nullptr, job.header};
  out.result = exporter.write(input, params, outDir, writeProgress);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace spira
