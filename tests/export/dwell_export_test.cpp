// A dwell (path/dwell.h) in the exported programs: the arc goes out at the dwell's point, the torch
// lifts the travel clearance along its axis, waits there the dwell's seconds with the arc off, comes
// back to the same point and strikes a new arc. Read back from the written files.
#include <gtest/gtest.h>

#include <algorithm>

#include "builtin_plugins.h"
#include "export_test_data.h"
#include "krl_reader.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/path/dwell.h"
#include "spira/pipeline/export_job.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/robotcell/cell_file.h"
#include "support/test_support.h"
#include "tp_reader.h"

namespace spira {
namespace {

constexpr double kClearance = 25.0;
constexpr double kWritten = 1e-3;  // mm: targets are written with 3 decimals
constexpr size_t kDwellPoint = 18;

// Three revolutions of a helix, the arc on throughout, with `seconds` of dwell at kDwellPoint.
Trajectory dwellPlan(double seconds)
{
  Trajectory plan = test::cylinderPlan(3, 12, 20.0, 2.0);
  std::vector<double> dwell(plan.size(), 0.0);
  dwell[kDwellPoint] = seconds;
  plan.extra[kDwellChannel] = dwell;
  return plan;
}

ExportOutcome runJob(const std::string& id, const Trajectory& plan, const RobotCell* cell,
                     const std::filesystem::path& dir, ParamSet params = ParamSet())
{
  ExportJob job;
  job.exporterId = id;
  job.exporterParams = std::move(params);
  job.exporterParams.set("process_command", std::string("speed_analog"));
  job.prep.travelClearance = kClearance;
  job.cell = cell;
  job.header = test::testHeader();
  NullProgress progress;
  return exportTrajectory(builtinRegistry(), plan, job, dir, progress);
}

size_t triggersWith(const test::KrlMove& m, const std::string& text)
{
  return static_cast<size_t>(
      std::count_if(m.triggers.begin(), m.triggers.end(),
                    [&text](const std::string& t) { return t.find(text) != std::string::npos; }));
}

size_t arcStarts(const test::KrlRun& run)
{
  size_t n = 0;
  for (const test::KrlMove& m : run.moves) n += triggersWith(m, "$OUT[1]=TRUE");
  return n;
}

TEST(DwellExport, KrlStopsTheArcLiftsWaitsAndStrikesAgainAtThePoint)
{
  const Trajectory plan = dwellPlan(7.5);
  const TrajectoryPoint& at = plan.points[kDwellPoint];
  test::TempDir dir, plainDir;
  const ExportOutcome out = runJob("export.krl", plan, nullptr, dir.path());
  EXPECT_EQ(out.dwells, 1u);
  Trajectory plain = plan;
  plain.extra.clear();
  EXPECT_EQ(runJob("export.krl", plain, nullptr, plainDir.path()).dwells, 0u);

  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  const test::KrlRun plainRun = test::runKrl(plainDir.path(), "spira_part");
  EXPECT_TRUE(plainRun.waitAfter.empty());
  EXPECT_EQ(arcStarts(plainRun), 1u);
  EXPECT_EQ(arcStarts(run), 2u);  // exactly one more arc start

  ASSERT_EQ(run.waitAfter.size(), 1u);
  EXPECT_EQ(run.waitSeconds[0], 7.5);
  const size_t w = run.waitAfter[0];
  ASSERT_GT(w, 0u);
  ASSERT_LT(w + 2, run.moves.size());
  const test::KrlMove& arrive = run.moves[w - 1];
  const test::KrlMove& lift = run.moves[w];
  const test::KrlMove& back = run.moves[w + 1];
  // The torch arrives at the dwell's point depositing and the arc goes out there (at its end).
  EXPECT_LT((arrive.pose.xyz - at.position).norm(), kWritten);
  EXPECT_EQ(triggersWith(arrive, "DISTANCE=1 DELAY=0 DO $OUT[1]=FALSE"), 1u);
  EXPECT_FALSE(arrive.approximated);
  // Lifted the clearance along the build direction (the torch axis), an exact linear move.
  const Vec3 lifted = at.position + kClearance * at.build;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(lift.pose.xyz[k], lifted[k], kWritten) << k;
  EXPECT_EQ(lift.motion, "LIN");
  EXPECT_FALSE(lift.approximated);
  EXPECT_TRUE(lift.triggers.empty());
  // Back to the same point, where the new arc is struck (on the move that leaves it).
  EXPECT_LT((back.pose.xyz - at.position).norm(), kWritten);
  EXPECT_EQ(back.motion, "LIN");
  EXPECT_FALSE(back.approximated);
  EXPECT_EQ(triggersWith(back, "$OUT[1]"), 0u);
  EXPECT_EQ(triggersWith(run.moves[w + 2], "DISTANCE=0 DELAY=0 DO $OUT[1]=TRUE"), 1u);
  // No wire-feed output while the arc is off.
  for (const test::KrlMove* m : {&lift, &back}) EXPECT_EQ(triggersWith(*m, "$ANOUT"), 0u);
  // The rest of the program is the plan's: two more targets (the lift and the point again).
  EXPECT_EQ(run.moves.size(), plainRun.moves.size() + 2);
}

// With an end job the arc-off trigger switches the job; the strike after the wait selects the weld
// job again, as at a sub-path's start.
TEST(DwellExport, KrlSelectsTheWeldJobAgainAfterTheWait)
{
  ParamSet params;
  params.set("job_output", std::int64_t{10});
  params.set("weld_job", std::int64_t{3});
  params.set("end_job", std::int64_t{5});
  test::TempDir dir;
  runJob("export.krl", dwellPlan(7.5), nullptr, dir.path(), params);
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  ASSERT_EQ(run.waitAfter.size(), 1u);
  const size_t w = run.waitAfter[0];
  EXPECT_EQ(triggersWith(run.moves[w - 1], "SPIRA_JOB=5"), 1u);
  EXPECT_EQ(triggersWith(run.moves[w + 2], "SPIRA_JOB=3"), 1u);
  size_t weldJobs = 0;
  for (const test::KrlMove& m : run.moves) weldJobs += triggersWith(m, "SPIRA_JOB=3");
  EXPECT_EQ(weldJobs, 1u);  // the first is selected before the first move, not by a trigger
}

TEST(DwellExport, TpEndsTheArcLiftsWaitsAndStartsItAgain)
{
  const Trajectory plan = dwellPlan(12.25);
  const TrajectoryPoint& at = plan.points[kDwellPoint];
  test::TempDir dir;
  runJob("export.fanuc_tp", plan, nullptr, dir.path());
  const test::TpRun run = test::runTp(dir.path(), "SPIRA_PART");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  ASSERT_EQ(run.arcStartAfter.size(), 2u);
  ASSERT_EQ(run.arcEndAfter.size(), 2u);
  ASSERT_EQ(run.waitAfter.size(), 1u);
  EXPECT_EQ(run.waitSeconds[0], 12.25);
  EXPECT_NE(std::find(run.statements.begin(), run.statements.end(), "WAIT 12.25(sec)"), run.statements.end());
  const size_t w = run.waitAfter[0];
  // Arc End at the point, the lift, the wait, back to the point, Arc Start there.
  EXPECT_EQ(run.arcEndAfter[0], w - 1);
  EXPECT_EQ(run.arcStartAfter[1], w + 1);
  EXPECT_LT((test::tpPose(run.moves[w - 1].pos).translation() - at.position).norm(), kWritten);
  EXPECT_LT((test::tpPose(run.moves[w + 1].pos).translation() - at.position).norm(), kWritten);
  const Vec3 lifted = at.position + kClearance * at.build;
  const Vec3 liftAt = test::tpPose(run.moves[w].pos).translation();
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(liftAt[k], lifted[k], kWritten) << k;
  for (size_t m : {w - 1, w, w + 1}) {
    EXPECT_EQ(run.moves[m].type, 'L') << m;
    EXPECT_EQ(run.moves[m].termination, "FINE") << m;
  }
  EXPECT_EQ(run.moves[w].options.find("AO["), std::string::npos);
}

// On a real cell the lift is solved like the travel moves: reachable, with its own S and T, and
// written in the robot's base frame along the torch axis of the dwell's point.
TEST(DwellExport, TheLiftIsSolvedOnARealCell)
{
  const RobotCell cell(readCellFile(test::sourceDir() / "resources/cells/kuka_kr16_2_table.cell"));
  test::TempDir dir;
  const ExportOutcome out = runJob("export.krl", dwellPlan(3.0), &cell, dir.path());
  EXPECT_EQ(out.unreachableTargets, 0u);
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  ASSERT_EQ(run.waitAfter.size(), 1u);
  EXPECT_EQ(run.waitSeconds[0], 3.0);
  const size_t w = run.waitAfter[0];
  const test::KrlMove& arrive = run.moves[w - 1];
  const test::KrlMove& lift = run.moves[w];
  EXPECT_TRUE(lift.pose.s.has_value());
  EXPECT_TRUE(lift.pose.t.has_value());
  const Vec3 step = lift.pose.xyz - arrive.pose.xyz;
  EXPECT_NEAR(step.norm(), kClearance, 2 * kWritten);
  const Vec3 axis = test::krlPose(arrive.pose).linear().col(2);
  EXPECT_NEAR(std::abs(axis.dot(step)), kClearance, 2 * kWritten);
  EXPECT_LT((run.moves[w + 1].pose.xyz - arrive.pose.xyz).norm(), 2 * kWritten);
  EXPECT_EQ(arcStarts(run), 2u);
}

// Dwells at a sub-path's ends wait on the travel there: the retract after its last point, the
// approach before its first; one at the plan's very first point waits lifted before the first strike.
TEST(DwellExport, DwellsAtTheEndsOfSubPathsWaitOnTheTravel)
{
  Trajectory plan = test::cylinderPlan(1, 12, 20.0, 2.0);
  const size_t n0 = plan.size();
  Trajectory second = test::cylinderPlan(1, 12, 10.0, 2.0);
  for (TrajectoryPoint& p : second.points) {
    p.position += Vec3(0, 0, 10);
    p.path = 1;
    plan.points.push_back(p);
  }
  std::vector<double> dwell(plan.size(), 0.0);
  dwell[0] = 1.5;
  dwell[n0 - 1] = 2.5;
  dwell[n0] = 4.0;
  plan.extra[kDwellChannel] = dwell;
  test::TempDir dir;
  EXPECT_EQ(runJob("export.krl", plan, nullptr, dir.path()).dwells, 3u);
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  EXPECT_EQ(arcStarts(run), 2u);  // the arc stops at a sub-path's end anyway
  ASSERT_EQ(run.waitAfter.size(), 3u);
  EXPECT_EQ(run.waitSeconds, (std::vector<double>{1.5, 2.5, 4.0}));
  const auto liftedFrom = [&plan](size_t i) {
    return plan.points[i].position + kClearance * plan.points[i].build;
  };
  // The program's first target is the lift (after the exporter's own approach to it).
  const size_t first = run.waitAfter[0];
  EXPECT_EQ(run.moves[first].target, "XP0");
  EXPECT_LT((run.moves[first].pose.xyz - liftedFrom(0)).norm(), kWritten);
  EXPECT_LT((run.moves[first + 1].pose.xyz - plan.points[0].position).norm(), kWritten);
  EXPECT_LT((run.moves[run.waitAfter[1]].pose.xyz - liftedFrom(n0 - 1)).norm(), kWritten);
  EXPECT_LT((run.moves[run.waitAfter[1] - 1].pose.xyz - plan.points[n0 - 1].position).norm(), kWritten);
  EXPECT_LT((run.moves[run.waitAfter[2]].pose.xyz - liftedFrom(n0)).norm(), kWritten);
  EXPECT_LT((run.moves[run.waitAfter[2] + 1].pose.xyz - plan.points[n0].position).norm(), kWritten);
}

// A program waits only where the arc is off: a dwell left on an arc-on point was not laid out.
TEST(DwellExport, AWaitWithTheArcOnIsRefused)
{
  const Trajectory plan = dwellPlan(2.0);
  test::TempDir dir;
  try {
    test::runExporter("export.krl", plan, nullptr, ParamSet(), dir.path());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("point 18 waits 2 s with the arc on"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace spira
