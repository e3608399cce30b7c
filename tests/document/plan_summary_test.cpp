// The typed summary of a planned document, read from its typed stage reports, and report.json's
// layout of those reports.
#include <gtest/gtest.h>

#include <limits>
#include <memory>

#include <nlohmann/json.hpp>

#include "spira/document/plan_report.h"
#include "spira/document/results.h"
#include "spira/pipeline/planned_path.h"
#include "spira/pipeline/program_header.h"

namespace spira::test {
namespace {

Results plannedResults()
{
  SpiralStageReport spiral;
  spiral.partType = "closed";
  spiral.revolutions = 31;
  spiral.collapsedRevolutions = 2;
  spiral.points = 11160;
  spiral.heightMin = 1.83;
  spiral.heightMax = 2.17;
  spiral.rampHeightMin = 1.8;
  spiral.rampHeightMax = 2.2;
  spiral.pathLength = 5712.5;
  spiral.h = 2.0;
  spiral.hMin = 1.8;
  spiral.hMax = 2.2;
  spiral.heightTolerance = 0.01;
  spiral.closurePoint = Vec3(0.0, 0.0, 60.0);
  spiral.buildTime = 1960.0;
  spiral.feasible = false;
  spiral.solid = SolidRecord{};
  spiral.solid->wallThickness = {4.0, 3.5, 4.5};
  DepositCheckRecord& check = spiral.depositCheck;
  check.summary = "2 beads are too thin";
  check.heightMin = 1.1;
  check.heightMax = 2.3;
  check.flagged = 2;
  check.coverage = CoverageRecord{};
  check.coverage->uncoveredFraction = 0.025;
  check.flaggedPoints = {{7, "thin", 1.1, Vec3::Zero()},
                         {9, "unsupported", std::numeric_limits<double>::infinity(), Vec3::Zero()}};
  ProcessStageReport process;
  process.withinLimits = true;
  KinematicsStageReport kinematics;
  kinematics.motion.cell = "KUKA KR 16-2 on a table";
  kinematics.motion.reachable = true;
  kinematics.seconds = 4.5;
  Results r;
  r.setSpiral(std::make_shared<const Trajectory>(), std::make_shared<const SpiralStageReport>(spiral));
  r.setProcess(std::make_shared<const Trajectory>(), std::make_shared<const ProcessStageReport>(process));
  r.setKinematics(std::make_shared<const KinematicsResult>(),
                  std::make_shared<const KinematicsStageReport>(kinematics));
  return r;
}

TEST(PlanSummary, ReadsEveryFigureTheViewsShowFromTheStageReports)
{
  const std::optional<PlanReportSummary> s = planSummaryOf(plannedResults());
  ASSERT_TRUE(s);
  EXPECT_EQ(s->partType, "closed");
  EXPECT_EQ(s->revolutions, 31);
  EXPECT_EQ(s->collapsedRevolutions, 2);
  EXPECT_EQ(s->points, 11160);
  EXPECT_TRUE(s->closed);
  EXPECT_DOUBLE_EQ(s->rampHeightMax, 2.2);
  ASSERT_TRUE(s->window);
  EXPECT_DOUBLE_EQ(s->window->hMin, 1.8);
  EXPECT_DOUBLE_EQ(s->window->tolerance, 0.01);
  EXPECT_TRUE(s->window->outside(1.78));
  EXPECT_FALSE(s->window->outside(1.795));
  ASSERT_TRUE(s->solidWall);
  EXPECT_DOUBLE_EQ(s->solidWall->thinnest, 3.5);
  EXPECT_EQ(s->feasible, std::optional<bool>(false));
  EXPECT_EQ(s->depositSummary, "2 beads are too thin");
  EXPECT_DOUBLE_EQ(s->uncoveredFraction, 0.025);
  ASSERT_EQ(s->flaggedPoints.size(), 2u);
  EXPECT_EQ(s->flaggedPoints[0].point, 7u);
  EXPECT_EQ(s->flaggedPoints[0].height, std::optional<double>(1.1));
  EXPECT_FALSE(s->flaggedPoints[1].height);  // nothing below it
  EXPECT_EQ(s->buildTime, std::optional<double>(1960.0));
  EXPECT_EQ(s->cell, "KUKA KR 16-2 on a table");
}

TEST(PlanSummary, WithoutAProcessReportThereIsNoBuildTime)
{
  Results r = plannedResults();
  r.invalidateFrom(Stage::Process);
  const std::optional<PlanReportSummary> s = planSummaryOf(r);
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->buildTime);
  EXPECT_EQ(s->cell, "");
  EXPECT_FALSE(planSummaryOf(Results()));
  EXPECT_FALSE(planWindow(Results()));
}

// report.json: the spiral's keys at the top, the process's under "process", the motion's at the
// top with its wall time under timings_s; the stored stage's own "seconds" stays out.
TEST(PlanSummary, MergedReportHasReportJsonsLayout)
{
  const nlohmann::json merged = mergedPlanReport(plannedResults());
  EXPECT_EQ(merged.at("build_time_s"), 1960.0);
  EXPECT_EQ(merged.at("process").at("within_limits"), true);
  EXPECT_FALSE(merged.at("process").contains("build_time_s"));
  EXPECT_EQ(merged.at("reachable"), true);
  EXPECT_EQ(merged.at("cell"), "KUKA KR 16-2 on a table");
  EXPECT_EQ(merged.at("timings_s").at("kinematics"), 4.5);
  EXPECT_FALSE(merged.contains("seconds"));
  EXPECT_EQ(merged.at("closure_point"), nlohmann::json::array({0.0, 0.0, 60.0}));
  EXPECT_TRUE(nlohmann::json::parse(merged.dump())
                  .at("deposit_check")
                  .at("flagged_points")
                  .at(1)
                  .at("height")
                  .is_null());
  // A plan folder's report.json reads back to the same summary.
  const PlanReportSummary back = summarisePlanReport(nlohmann::json::parse(merged.dump()), "report.json");
  const PlanReportSummary direct = *planSummaryOf(plannedResults());
  EXPECT_EQ(back.revolutions, direct.revolutions);
  EXPECT_EQ(back.buildTime, direct.buildTime);
  EXPECT_EQ(back.cell, direct.cell);
  ASSERT_EQ(back.flaggedPoints.size(), 2u);
  EXPECT_FALSE(back.flaggedPoints[1].height);
  EXPECT_EQ(back.window->hMax, 2.2);
}

TEST(ProgramHeader, NamesThePartTheCellTheUtcDateAndThePlan)
{
  const PlanReportSummary plan = *planSummaryOf(plannedResults());
  const auto h = programHeader("dome.stl", "", plan, 86400 * 365);  // 1971-01-01 00:00 UTC
  EXPECT_EQ(h.at("part"), "dome.stl");
  EXPECT_EQ(h.at("cell"), "none (targets in the part frame)");
  EXPECT_EQ(h.at("date"), "1971-01-01 00:00 UTC");
  EXPECT_EQ(h.at("plan"), "closed part, 31 revolutions, deposit 1.83 .. 2.17 mm, path 5712 mm");
}

// Export follows the path the robot was solved for (its torch tilts cleared collisions), with the
// points the plan left in collision; without a cell, the process stage's path.
TEST(PlannedPath, IsTheKinematicsPathWhenSolvedElseTheProcessPath)
{
  Trajectory process;
  process.points.resize(3);
  Results r;
  r.setProcess(std::make_shared<const Trajectory>(process));
  EXPECT_EQ(plannedPathOf(r).trajectory, r.process);
  EXPECT_TRUE(plannedPathOf(r).collision.empty());

  auto solved = std::make_shared<KinematicsResult>();
  solved->path = process;
  solved->path.points[1].normal = Vec3::UnitZ();  // tilted to clear a collision
  solved->checks = {KinematicsCheck{}, KinematicsCheck{}, KinematicsCheck{}};
  solved->checks[2].collision = true;
  r.setKinematics(solved);
  const PlannedPath p = plannedPathOf(r);
  EXPECT_EQ(p.trajectory.get(), &r.kinematics->path);
  EXPECT_EQ(p.collision, (std::vector<bool>{false, false, true}));
}

}  // namespace
}  // namespace spira::test
