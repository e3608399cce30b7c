// The typed summary of a planned document: the stage reports merged as report.json has them and
// read once, so no view reads a report by key; a damaged report gives no summary instead of an
// exception in a view.
#include <gtest/gtest.h>

#include <memory>

#include <nlohmann/json.hpp>

#include "spira/document/plan_report.h"
#include "spira/document/results.h"
#include "spira/pipeline/planned_path.h"
#include "spira/pipeline/program_header.h"

namespace spira::test {
namespace {

std::shared_ptr<const nlohmann::json> share(nlohmann::json j)
{
  return std::make_shared<const nlohmann::json>(std::move(j));
}

Results plannedResults()
{
  Results r;
  r.setReport(
      Stage::Spiral,
      share({{"part_type", "closed"},
             {"n_revolutions", 31},
             {"collapsed_revolutions", 2},
             {"n_points", 11160},
             {"height_min", 1.83},
             {"height_max", 2.17},
             {"ramp_height_min", 1.8},
             {"ramp_height_max", 2.2},
             {"path_length", 5712.5},
             {"h", 2.0},
             {"h_min", 1.8},
             {"h_max", 2.2},
             {"height_tolerance_mm", 0.01},
             {"closure_point", {0.0, 0.0, 60.0}},
             {"feasible", false},
             {"solid", {{"wall_thickness_mm", {{"median", 4.0}, {"thinnest", 3.5}, {"thickest", 4.5}}}}},
             {"deposit_check",
              {{"summary", "2 beads are too thin"},
               {"height_min", 1.1},
               {"height_max", 2.3},
               {"flagged", 2},
               {"coverage", {{"uncovered_fraction", 0.025}}},
               {"flagged_points",
                {{{"point", 7}, {"kind", "thin"}, {"height", 1.1}},
                 {{"point", 9}, {"kind", "unsupported"}, {"height", nullptr}}}}}}}));
  r.setReport(Stage::Process, share({{"build_time_s", 1960.0}, {"within_limits", true}}));
  r.setReport(Stage::Kinematics, share({{"cell", "KUKA KR 16-2 on a table"}, {"reachable", true}}));
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
  EXPECT_FALSE(s->flaggedPoints[1].height);
  EXPECT_EQ(s->buildTime, std::optional<double>(1960.0));
  EXPECT_EQ(s->cell, "KUKA KR 16-2 on a table");  // the motion report's keys sit at the top
}

TEST(PlanSummary, ProcessReportGoesUnderProcessAsInReportJson)
{
  const nlohmann::json merged = mergedPlanReport(plannedResults());
  EXPECT_EQ(merged.at("process").at("build_time_s"), 1960.0);
  EXPECT_FALSE(merged.contains("build_time_s"));
  EXPECT_EQ(merged.at("reachable"), true);
}

TEST(PlanSummary, NoSpiralReportOrADamagedOneGivesNoSummary)
{
  EXPECT_FALSE(planSummaryOf(Results()));
  Results damaged = plannedResults();
  damaged.setReport(Stage::Spiral, share({{"n_revolutions", "thirty"}}));
  EXPECT_FALSE(planSummaryOf(damaged));
  EXPECT_FALSE(planWindow(damaged));
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
