// solveSubPaths: a plan of several sub-paths is solved sub-path by sub-path, each with its own
// seed and configuration, exactly as if each were solved alone; the report indexes the whole path.
#include <gtest/gtest.h>

#include "export_test_data.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/pipeline/plan_motion.h"
#include "spira/pipeline/prep_schema.h"
#include "spira/pipeline/sub_paths.h"
#include "spira/robotcell/cell_file.h"
#include "support/test_support.h"

namespace spira {
namespace {

Trajectory twoPaths()
{
  Trajectory plan;
  for (int k = 0; k < 2; ++k) {
    Trajectory t = test::cylinderPlan(1, 24, k == 0 ? 40.0 : 15.0, 2.0);
    for (TrajectoryPoint& p : t.points) {
      p.position += Vec3(k == 0 ? 0.0 : 60.0, 0.0, 4.0 * k);
      p.path = k;
      plan.points.push_back(p);
    }
  }
  plan.extra["dwell"] = std::vector<double>(plan.size(), 0.5);
  return plan;
}

TEST(SubPaths, RangesSlicesAndAppendRoundTrip)
{
  const Trajectory plan = twoPaths();
  const std::vector<SubPathRange> ranges = subPathRanges(plan);
  ASSERT_EQ(ranges.size(), 2u);
  EXPECT_EQ(ranges[0].begin, 0u);
  EXPECT_EQ(ranges[0].end, 25u);
  EXPECT_EQ(ranges[1].path, 1);
  EXPECT_EQ(ranges[1].end, plan.size());
  Trajectory again;
  for (const SubPathRange& r : ranges) appendTrajectory(again, subTrajectory(plan, r));
  EXPECT_EQ(again, plan);
  Trajectory bare = subTrajectory(plan, ranges[0]);
  bare.extra.clear();
  appendTrajectory(bare, subTrajectory(plan, ranges[1]));  // a channel only on one side: zeros
  ASSERT_EQ(bare.extra.at("dwell").size(), plan.size());
  EXPECT_EQ(bare.extra.at("dwell")[0], 0.0);
  EXPECT_EQ(bare.extra.at("dwell")[30], 0.5);
}

TEST(SubPaths, EachSubPathIsSolvedAsIfAlone)
{
  const RobotCell cell(readCellFile(test::sourceDir() / "resources/cells/kuka_kr16_2_table.cell"));
  const Trajectory plan = twoPaths();
  const MotionParams params = motionParamsFor(cell, MotionSettings{});
  NullProgress progress;
  std::vector<JointPathSetup> setups;
  const MotionResult whole = solveSubPaths(cell, plan, params, progress, &setups);
  ASSERT_EQ(whole.joints.size(), plan.size());
  ASSERT_EQ(setups.size(), 2u);
  size_t layers = 0;
  for (const SubPathRange& r : subPathRanges(plan)) {
    const Trajectory piece = subTrajectory(plan, r);
    const MotionResult alone =
        solveMotion(cell.ik(), cell.convention(), piece, cell.seededSetup(piece), params, progress);
    for (size_t i = 0; i < piece.size(); ++i) {
      for (size_t a = 0; a < 6; ++a)
        EXPECT_NEAR(whole.joints.points[r.begin + i].robotDeg[a], alone.joints.points[i].robotDeg[a], 1e-9);
      EXPECT_EQ(whole.joints.points[r.begin + i].kukaStatus, alone.joints.points[i].kukaStatus);
    }
    for (const LayerSpin& l : alone.report.layers) {
      ASSERT_LT(layers, whole.report.layers.size());
      EXPECT_EQ(whole.report.layers[layers++].firstPoint, l.firstPoint + r.begin);
    }
  }
  EXPECT_EQ(layers, whole.report.layers.size());
  EXPECT_TRUE(whole.report.reachable);
}

TEST(SubPaths, PrepSchemaReadsLeadAndTravelSettings)
{
  ParamSet v;
  v.set("wfs_lead", true);
  v.set("lead_dead_time", 0.25);
  v.set("lead_rise_time", 0.05);
  v.set("lead_fall_time", 0.2);
  v.set("travel_clearance", 40.0);
  v.set("travel_speed", 80.0);
  const PrepParams p = prepParamsFrom(v);
  EXPECT_TRUE(p.leadWireFeed);
  EXPECT_DOUBLE_EQ(p.wireFeedLag.deadTime, 0.25);
  EXPECT_DOUBLE_EQ(p.wireFeedLag.riseTimeConstant, 0.05);
  EXPECT_DOUBLE_EQ(p.wireFeedLag.fallTimeConstant, 0.2);
  EXPECT_DOUBLE_EQ(p.travelClearance, 40.0);
  EXPECT_DOUBLE_EQ(p.travelSpeed, 80.0);
  EXPECT_FALSE(prepParamsFrom(ParamSet()).leadWireFeed);
  v.set("lead_dead_time", -1.0);
  EXPECT_THROW(prepParamsFrom(v), InputError);
}

}  // namespace
}  // namespace spira
