// A dwell (path/dwell.h) in RAPID: the arc ends with ArcLEnd at the dwell's point, the torch lifts the
// travel clearance with MoveL fine, waits with WaitTime \InPos, and ArcLStart strikes again at the
// same point. Read back with the independent reader.
#include <gtest/gtest.h>

#include "builtin_plugins.h"
#include "export/export_test_data.h"
#include "rapid_reader.h"
#include "spira/base/progress.h"
#include "spira/path/dwell.h"
#include "spira/pipeline/export_job.h"
#include "support/test_support.h"

namespace spira {
namespace {

TEST(RapidDwell, EndsTheArcLiftsWaitsAndStrikesAgainAtThePoint)
{
  constexpr size_t kDwellPoint = 18;
  constexpr double kClearance = 25.0;
  Trajectory plan = test::cylinderPlan(3, 12, 20.0, 2.0);
  std::vector<double> dwell(plan.size(), 0.0);
  dwell[kDwellPoint] = 7.5;
  plan.extra[kDwellChannel] = dwell;

  ExportJob job;
  job.exporterId = "export.rapid";
  job.prep.travelClearance = kClearance;
  job.header = test::testHeader();
  test::TempDir dir;
  NullProgress progress;
  const ExportOutcome out = exportTrajectory(builtinRegistry(), plan, job, dir.path(), progress);
  EXPECT_EQ(out.dwells, 1u);

  const test::RapidRun run = test::runRapid(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  size_t starts = 0, ends = 0, waits = 0;
  for (size_t m = 0; m < run.moves.size(); ++m) {
    const test::RapidMove& move = run.moves[m];
    starts += move.instruction == "ArcLStart";
    ends += move.instruction == "ArcLEnd";
    if (move.instruction != "WaitTime") continue;
    ++waits;
    EXPECT_DOUBLE_EQ(move.wait, 7.5);
    ASSERT_GE(m, 2u);
    ASSERT_LT(m + 1, run.moves.size());
    const test::RapidMove& end = run.moves[m - 2];
    const test::RapidMove& lift = run.moves[m - 1];
    const test::RapidMove& back = run.moves[m + 1];
    EXPECT_EQ(end.instruction, "ArcLEnd");
    EXPECT_EQ(lift.instruction, "MoveL");
    EXPECT_EQ(lift.args[2], "fine");
    EXPECT_EQ(back.instruction, "ArcLStart");
    // Targets in the part frame (no cell): the arc ends and strikes again at the dwell's point, and
    // the torch waits the clearance above it.
    const Vec3 at = plan.points[kDwellPoint].position;
    const Transform endPose = test::rapidPose(run.data.at(end.args[0]).value);
    const Transform liftPose = test::rapidPose(run.data.at(lift.args[0]).value);
    const Transform backPose = test::rapidPose(run.data.at(back.args[0]).value);
    EXPECT_LT((endPose.translation() - at).norm(), 1e-3);
    EXPECT_LT((backPose.translation() - at).norm(), 1e-3);
    EXPECT_NEAR((liftPose.translation() - at).norm(), kClearance, 1e-3);
  }
  EXPECT_EQ(waits, 1u);
  EXPECT_EQ(starts, 2u);
  EXPECT_EQ(ends, 2u);
}

}  // namespace
}  // namespace spira
