// spira-cli plan PROJECT.spira runs the thermal stage the project switches on: report.json gains
// its "thermal" report, and --save stores the stage's result in the project, as the GUI's Plan does.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "spira/document/document.h"
#include "spira/document/project_file.h"
#include "spira/mesh/mesh_primitives.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

TEST(CliPlanThermal, AProjectWithTheStageOnReportsAndSavesIt)
{
  TempDir dir;
  Document doc;
  Part part;
  part.name = "wall";
  part.mesh = std::make_shared<const TriangleMesh>(makeOpenCylinder(20.0, 40.0, 48, 20));
  doc.setPart(part);
  doc.setParam(PlanSettings::kThermalSection, "enabled", true);
  doc.setParam(PlanSettings::kThermalSection, "interpass_max", 300.0);
  const fs::path project = dir / "wall.spira";
  doc.saveAs(project);

  const CliRun r = runCli({"plan", project.string(), "-o", (dir / "plan").string(), "--save"});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const nlohmann::json report = nlohmann::json::parse(readBytes(dir / "plan" / "report.json"));
  ASSERT_TRUE(report.contains("thermal")) << report.dump(2);
  EXPECT_EQ(report["thermal"]["material"], "G3Si1");
  EXPECT_EQ(report["thermal"]["interpass_limit_C"], 300.0);
  EXPECT_GT(report["thermal"]["max_interpass_C"].get<double>(), 20.0);

  const DocumentState saved = loadProject(project);
  ASSERT_TRUE(saved.results.thermal && saved.results.reports.thermal);
  EXPECT_EQ(saved.results.thermal->pointCount(), saved.results.process->size());
  EXPECT_EQ(saved.results.reports.thermal->maxInterpass, report["thermal"]["max_interpass_C"].get<double>());
  EXPECT_FALSE(saved.results.thermal->frames.empty());

  // Switched off again, the plan has no thermal report.
  Document off;
  off.open(project);
  off.setParam(PlanSettings::kThermalSection, "enabled", false);
  EXPECT_FALSE(off.results().thermal);
  off.save();
  const CliRun plain = runCli({"plan", project.string(), "-o", (dir / "plain").string()});
  ASSERT_EQ(plain.exitCode, 0) << plain.err << plain.out;
  EXPECT_FALSE(nlohmann::json::parse(readBytes(dir / "plain" / "report.json")).contains("thermal"));
}

}  // namespace
}  // namespace spira::test
