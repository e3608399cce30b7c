// A two-branch plan through the whole export pipeline on the bundled ABB cell (preparation, IK of
// the prepared points, travel between the sub-paths): one ArcLStart/ArcLEnd per sub-path, a MoveJ
// between them, one cfx per sub-path, and every written target reachable in its written confdata.
#include <gtest/gtest.h>

#include <set>

#include "builtin_plugins.h"
#include "export/export_test_data.h"
#include "rapid_reader.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/kinematics/abb_confdata.h"
#include "spira/pipeline/export_job.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
#include "support/test_support.h"

namespace spira {
namespace {

TEST(RapidAbbCell, TwoSubPathsThroughThePipeline)
{
  Trajectory plan = test::cylinderPlan(2, 36, 30.0, 2.0);
  const Trajectory upper = test::cylinderPlan(2, 36, 30.0, 2.0);
  for (TrajectoryPoint p : upper.points) {
    p.position.z() += 20.0;
    p.path = 1;
    plan.points.push_back(p);
  }
  const RobotCell cell(
      readCellFile(test::sourceDir() / "resources" / "cells" / "abb_irb1600_positioner.cell"));
  ExportJob job;
  job.exporterId = "export.rapid";
  job.cell = &cell;
  job.header = test::testHeader();
  test::TempDir dir;
  NullProgress progress;
  const ExportOutcome out = exportTrajectory(builtinRegistry(), plan, job, dir.path(), progress);
  EXPECT_EQ(out.subPaths, 2u);
  EXPECT_EQ(out.unreachableTargets, 0u);

  const test::RapidRun run = test::runRapid(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  size_t starts = 0, ends = 0, travels = 0;
  bool inArc = false;
  std::vector<std::set<int>> cfxPerArc;
  for (const test::RapidMove& m : run.moves) {
    if (m.instruction == "ArcLStart") {
      ++starts;
      EXPECT_FALSE(inArc);
      inArc = true;
      cfxPerArc.emplace_back();
    }
    if (m.instruction == "ArcLEnd") {
      ++ends;
      EXPECT_TRUE(inArc);
      inArc = false;
    }
    if (m.instruction == "MoveJ") {
      ++travels;
      EXPECT_FALSE(inArc);
    }
    if (inArc || m.instruction == "ArcLEnd")
      cfxPerArc.back().insert(static_cast<int>(run.data.at(m.args[0]).value[2][3].number));
  }
  EXPECT_EQ(starts, 2u);
  EXPECT_EQ(ends, 2u);
  EXPECT_EQ(travels, 2u);  // to the approach, and from one sub-path's side to the next
  for (const auto& cfx : cfxPerArc) EXPECT_EQ(cfx.size(), 1u);

  const ArmIk& ik = cell.ik();
  const Transform tcpInverse = cell.record().tool.T_flange_tcp.inverse();
  size_t targets = 0;
  for (const auto& [name, d] : run.data) {
    if (d.type != "robtarget") continue;
    ++targets;
    std::array<int, 4> conf{};
    for (size_t k = 0; k < 4; ++k) conf[k] = static_cast<int>(d.value[2][k].number);
    // The IK returns one joint vector per arm configuration; cf1, cf4 and cf6 pick the turns of
    // axes 1, 4 and 6, so every in-limit turn of those is tried, as the controller does.
    bool named = false;
    for (const IkSolution& s : ik.solveAll(test::rapidPose(d.value) * tcpInverse))
      for (int t1 = -1; t1 <= 1; ++t1)
        for (int t4 = -1; t4 <= 1; ++t4)
          for (int t6 = -2; t6 <= 2; ++t6) {
            JointVector q = s.q;
            q[0] += 2.0 * kPi * t1;
            q[3] += 2.0 * kPi * t4;
            q[5] += 2.0 * kPi * t6;
            if (ik.chain().limitMargin(q) < 0.0) continue;
            // The written pose is rounded (0.001 mm, 1e-8 in the quaternion): an axis the path
            // holds at a quadrant boundary (axis 6 at 0) comes back a few 1e-6 deg across it.
            const std::array<int, 4> c = abbConfData(ik.model(), q).values;
            bool same = c[3] == conf[3];
            for (const auto& [axis, k] : {std::pair<int, size_t>{0, 0}, {3, 1}, {5, 2}}) {
              const double deg = radToDeg(q[axis]);
              same = same && deg >= 90.0 * conf[k] - 1e-3 && deg <= 90.0 * (conf[k] + 1) + 1e-3;
            }
            named = named || same;
          }
    EXPECT_TRUE(named) << name << " has no in-limit joint vector with its written confdata";
    EXPECT_GT(d.value[3][1].number, -36000.0);  // the turntable's E2 within its range
    EXPECT_LT(d.value[3][1].number, 36000.0);
  }
  EXPECT_EQ(targets, out.robotTargets + 2);  // + approach and retract
}

}  // namespace
}  // namespace spira
