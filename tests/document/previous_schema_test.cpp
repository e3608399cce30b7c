// A project saved by main before the stage reports were typed (tests/data/projects/README.md)
// opens with every stage and every report, and each typed report writes back exactly the keys and
// values that version stored, apart from the process report's build time, which the spiral report
// already carries.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "spira/document/plan_report.h"
#include "spira/document/project_file.h"
#include "spira/document/stage_report_codec.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

const std::filesystem::path kProject = sourceDir() / "tests/data/projects/open_cylinder_227a109.spira";

const nlohmann::json& storedReport(const nlohmann::json& project, const char* stage)
{
  return project.at("results").at("reports").at(stage).at("payload");
}

TEST(PreviousSchema, EveryStageAndReportOpens)
{
  const DocumentState s = loadProject(kProject);
  const Results& r = s.results;
  // Not simulated then: the thermal stage came later, and is optional.
  EXPECT_EQ(r.presentStages(), kAllStages & ~stageBit(Stage::Export) & ~stageBit(Stage::Thermal));
  EXPECT_FALSE(r.thermal || r.reports.thermal);
  ASSERT_TRUE(r.reports.field && r.reports.generatrices && r.reports.spiral && r.reports.process &&
              r.reports.kinematics);
  EXPECT_EQ(r.process->size(), 720u);
  EXPECT_EQ(r.kinematics->size(), 720u);
  EXPECT_EQ(r.reports.spiral->points, 720);
  EXPECT_EQ(r.reports.spiral->strategy, "isovalue");
  EXPECT_EQ(r.reports.kinematics->motion.cell, s.cell->name);
  EXPECT_GT(r.reports.kinematics->seconds, 0.0);
  const std::optional<PlanReportSummary> summary = planSummaryOf(r);
  ASSERT_TRUE(summary && summary->window);
  EXPECT_DOUBLE_EQ(summary->window->hMin, 1.8);
  EXPECT_DOUBLE_EQ(summary->window->hMax, 2.2);
  EXPECT_EQ(summary->feasible, std::optional<bool>(true));
}

template <class Report>
void expectSameKeys(const Report& typed, nlohmann::json stored, const char* stage)
{
  EXPECT_EQ(reportToJson(typed).dump(), stored.dump()) << stage;
}

TEST(PreviousSchema, TypedReportsWriteBackWhatWasStored)
{
  const nlohmann::json project = projectJsonOf(readBytes(kProject));
  const StageReports& r = loadProject(kProject).results.reports;
  expectSameKeys(*r.field, storedReport(project, "field"), "field");
  expectSameKeys(*r.generatrices, storedReport(project, "generatrices"), "generatrices");
  expectSameKeys(*r.spiral, storedReport(project, "spiral"), "spiral");
  expectSameKeys(*r.kinematics, storedReport(project, "kinematics"), "kinematics");
  nlohmann::json process = storedReport(project, "process");
  EXPECT_EQ(process.at("build_time_s"), storedReport(project, "spiral").at("build_time_s"));
  process.erase("build_time_s");
  expectSameKeys(*r.process, process, "process");
}

TEST(PreviousSchema, SavedAgainItReadsBackUnchanged)
{
  const DocumentState s = loadProject(kProject);
  TempDir dir;
  saveProject(s, dir / "again.spira");
  const DocumentState back = loadProject(dir / "again.spira");
  EXPECT_EQ(back.results.differingStages(s.results), 0u);
  EXPECT_TRUE(back.sameInputs(s));
}

}  // namespace
}  // namespace spira::test
