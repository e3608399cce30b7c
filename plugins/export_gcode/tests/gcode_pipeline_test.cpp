// export.gcode through exportTrajectory, as spira-cli and the desktop app run it: the path prepared
// (smoothed, decimated, sub-paths laid out with travel between them), a robot cell given with the job
// left unsolved, one arc per sub-path with the travel at the safe height, read back through the head.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "builtin_plugins.h"
#include "export/export_test_data.h"
#include "export_gcode/gcode_machine.h"
#include "export_gcode/head_kinematics.h"
#include "gcode_reader.h"
#include "spira/base/progress.h"
#include "spira/pipeline/export_job.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/robotcell/cell_file.h"
#include "support/test_support.h"

namespace spira {
namespace {

// A trunk helix and two arm helices above it, side by side: three sub-paths.
Trajectory threePathPlan()
{
  Trajectory plan;
  const std::array<Vec3, 3> offsets{Vec3(0, 0, 0), Vec3(-25, 0, 8), Vec3(25, 0, 8)};
  for (int k = 0; k < 3; ++k) {
    Trajectory t = test::cylinderPlan(k == 0 ? 3 : 2, 36, k == 0 ? 30.0 : 12.0, 2.0);
    for (TrajectoryPoint& p : t.points) {
      p.position += offsets[static_cast<size_t>(k)];
      p.path = k;
      plan.points.push_back(p);
    }
  }
  return plan;
}

// Distance to the planned polyline of one sub-path: the prepared path keeps within the chords'
// sagitta (0.11 mm) plus the chord tolerance (0.05 mm) of it.
double distanceToPath(const Vec3& q, const Trajectory& plan, int path)
{
  double best = 1e9;
  for (size_t i = 1; i < plan.size(); ++i) {
    if (plan.points[i].path != path || plan.points[i - 1].path != path) continue;
    const Vec3 a = plan.points[i - 1].position, d = plan.points[i].position - a;
    const double u = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + u * d - q).norm());
  }
  return best;
}

TEST(GcodePipeline, EverySubPathHasOneArcOnItsPathAndTheTravelRisesToTheSafeHeight)
{
  const Trajectory plan = threePathPlan();
  const std::filesystem::path machineFile =
      test::sourceDir() / "resources" / "machines" / "gantry_ca_head.machine";
  const GcodeMachine m = readMachineFile(machineFile);
  const RobotCell cell(readCellFile(test::sourceDir() / "resources" / "cells" / "kuka_kr16_2_table.cell"));
  test::TempDir dir;
  ExportJob job;
  job.exporterId = "export.gcode";
  job.exporterParams.set("machine", machineFile.string());
  job.exporterParams.set("decimals", std::int64_t{4});
  job.prep.travelClearance = 25.0;
  job.cell = &cell;  // a G-code export solves no cell
  job.header = test::testHeader();
  NullProgress progress;
  const ExportOutcome out = exportTrajectory(builtinRegistry(), plan, job, dir.path(), progress);
  EXPECT_EQ(out.subPaths, 3u);
  const test::GcodeRun run =
      test::readGcode(test::readBytes(dir / "spira_part.nc"), "M62 P0", "M63 P0", "M67 E0 Q", "G4 P");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  ASSERT_EQ(run.moves.size(), out.robotTargets + 2);

  double top = -1e9;
  for (const auto& p : plan.points) top = std::max(top, p.position.z());
  size_t arcs = 0, risen = 0;
  int arcPath = -1;
  double travelTop = -1e9;
  bool wasOn = false;
  for (const test::GcodeMove& mv : run.moves) {
    HeadAxes a;
    a.linear = Vec3(mv.axes.at('X'), mv.axes.at('Y'), mv.axes.at('Z'));
    a.rotaryDeg = {mv.axes.at('C'), mv.axes.at('A')};
    const Vec3 tip = headForward(m, a).tip - m.partOrigin;
    if (mv.arcOn && !wasOn) {
      ++arcs;
      if (arcs > 1 && travelTop >= top + 25.0 - 1e-3) ++risen;
      arcPath = -1;
      travelTop = -1e9;
    }
    if (mv.arcOn) {
      int nearest = -1;
      for (int k = 0; k < 3; ++k)
        if (distanceToPath(tip, plan, k) < 0.2) nearest = k;
      EXPECT_GE(nearest, 0) << "tip " << tip.transpose();
      if (arcPath < 0) arcPath = nearest;
      EXPECT_EQ(nearest, arcPath);
      EXPECT_EQ(arcPath, static_cast<int>(arcs) - 1);
    } else {
      travelTop = std::max(travelTop, tip.z());
    }
    wasOn = mv.arcOn;
  }
  EXPECT_EQ(arcs, 3u);
  EXPECT_EQ(risen, 2u);
  EXPECT_EQ(std::count(run.events.begin(), run.events.end(), "arc on"), 3);
  EXPECT_EQ(std::count(run.events.begin(), run.events.end(), "arc off"), 3);
}

}  // namespace
}  // namespace spira
