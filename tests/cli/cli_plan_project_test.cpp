// spira-cli plan PROJECT.spira: a saved project (part, placement, cell, settings) is planned by the
// pipeline the GUI's Plan runs and gives the same trajectory; --save stores the plan in the project,
// which export then takes; options that would override the project are a usage error.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>

#include "builtin_plugins.h"
#include "cli_runner.h"
#include "spira/base/progress.h"
#include "spira/document/document.h"
#include "spira/document/project_file.h"
#include "spira/io/import_service.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/pipeline/document_plan.h"
#include "spira/planning/joints_csv.h"
#include "spira/planning/plan_files.h"
#include "spira/robotcell/cell_file.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

// An open cylinder turned 30 degrees about z on the KUKA table cell, 90 points per revolution.
struct SavedProject {
  TempDir dir;
  fs::path file;
  DocumentState state;

  SavedProject()
  {
    Document doc;
    Part part;
    part.name = "open_cylinder";
    part.mesh = std::make_shared<const TriangleMesh>(makeOpenCylinder(50.0, 60.0, 90, 30));
    doc.setPart(part);
    doc.setPartPlacement(transformFromXyzRpy(Vec3(5.0, -3.0, 0.0), Vec3(0.0, 0.0, 0.5236)));
    doc.setCell(readCellFile(sourceDir() / "resources/cells/kuka_kr16_2_table.cell"));
    doc.setParam(doc.settings()->decomposerId, "points_per_rev", ParamValue(int64_t{90}));
    file = dir / "wall.spira";
    doc.saveAs(file);
    state = doc.state();
  }
};

TEST(CliPlanProject, SameTrajectoryAsTheGuiPlanAndSaveStoresIt)
{
  SavedProject p;
  NullProgress progress;
  const DocumentPlan gui = planDocument(p.state, builtinRegistry(), progress);
  ASSERT_TRUE(gui.results.kinematics);

  const fs::path out = p.dir / "plan";
  const CliRun r = runCli({"plan", p.file.string(), "-o", out.string(), "--save"});
  EXPECT_EQ(r.exitCode, gui.feasible && gui.motionOk ? 0 : 4) << r.err << r.out;
  EXPECT_EQ(readBytes(out / "trajectory.csv"), trajectoryCsv(gui.results.kinematics->path));
  EXPECT_EQ(readBytes(out / "joints.csv"), jointsCsv(gui.results.kinematics->joints));
  const nlohmann::json report = nlohmann::json::parse(readBytes(out / "report.json"));
  EXPECT_EQ(report.at("part"), "open_cylinder");
  EXPECT_EQ(report.at("cell"), p.state.cell->name);
  EXPECT_EQ(report.at("feasible"), gui.feasible);
  EXPECT_EQ(report.at("strategy"), "isovalue");  // the one name, as 'plan PART' writes it
  EXPECT_EQ(report.at("n_points"), gui.results.reports.spiral->points);

  const DocumentState saved = loadProject(p.file);
  ASSERT_TRUE(saved.results.process);
  ASSERT_TRUE(saved.results.kinematics);
  EXPECT_EQ(trajectoryCsv(*saved.results.process), trajectoryCsv(*gui.results.process));
  // The stored kinematics report differs only in its "seconds".
  EXPECT_EQ(jointsCsv(saved.results.kinematics->joints), jointsCsv(gui.results.kinematics->joints));
  EXPECT_EQ(trajectoryCsv(saved.results.kinematics->path), trajectoryCsv(gui.results.kinematics->path));

  const CliRun exported =
      runCli({"export", p.file.string(), "-o", (p.dir / "program").string(), "--format", "krl", "--force"});
  EXPECT_EQ(exported.exitCode, 0) << exported.err << exported.out;
}

// 'plan PART' with flags and 'plan PROJECT' holding that part with the same settings run one
// pipeline: the same path, joints and report but for the keys that say where the inputs came from.
TEST(CliPlanProject, PlanningThePartFileGivesThePlanOfTheProject)
{
  TempDir dir;
  const fs::path stl = sourceDir() / "resources/samples/open_cylinder.stl";
  const fs::path cell = sourceDir() / "resources/cells/fanuc_m20ia_positioner.cell";
  NullProgress progress;
  ImportedPart imported = importPart(builtinRegistry(), stl, nullptr, progress);
  Document doc;
  Part part;
  part.name = "open_cylinder";
  part.mesh = std::make_shared<const TriangleMesh>(std::move(imported.mesh));
  doc.setPart(part);
  doc.setCell(readCellFile(cell));
  doc.setParam(PlanSettings::kSpiralSection, "h", ParamValue(1.9));
  doc.setParam(doc.settings()->decomposerId, "points_per_rev", ParamValue(int64_t{120}));
  doc.saveAs(dir / "cylinder.spira");

  const CliRun fromProject =
      runCli({"plan", (dir / "cylinder.spira").string(), "-o", (dir / "project").string()});
  const CliRun fromPart = runCli({"plan", stl.string(), "--cell", cell.string(), "--h", "1.9",
                                  "--points-per-rev", "120", "-o", (dir / "part").string()});
  ASSERT_EQ(fromProject.exitCode, 0) << fromProject.err << fromProject.out;
  ASSERT_EQ(fromPart.exitCode, 0) << fromPart.err << fromPart.out;
  for (const char* file : {"trajectory.csv", "joints.csv"})
    EXPECT_EQ(readBytes(dir / "project" / file), readBytes(dir / "part" / file)) << file;
  nlohmann::json a = nlohmann::json::parse(readBytes(dir / "project" / "report.json"));
  nlohmann::json b = nlohmann::json::parse(readBytes(dir / "part" / "report.json"));
  for (const char* key : {"project", "part", "deposit_summary"}) EXPECT_EQ(a.erase(key), 1u) << key;
  for (const char* key : {"cell_file", "dropped_mm"}) EXPECT_EQ(b.erase(key), 1u) << key;
  for (nlohmann::json* j : {&a, &b})
    for (const char* key : {"timings_s", "kinematics_timings_s"}) EXPECT_EQ(j->erase(key), 1u) << key;
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.at("n_points"), b.at("n_points"));
  // The spiral's report carries the window it was planned for: h = 1.9 mm +/- 10 %.
  EXPECT_DOUBLE_EQ(b.at("h").get<double>(), 1.9);
  EXPECT_DOUBLE_EQ(b.at("h_min").get<double>(), 1.9 * 0.9);
  EXPECT_DOUBLE_EQ(b.at("h_max").get<double>(), 1.9 * 1.1);
}

TEST(CliPlanProject, OptionsThatWouldOverrideTheProjectAreUsageErrors)
{
  SavedProject p;
  const CliRun r = runCli({"plan", p.file.string(), "-o", (p.dir / "plan").string(), "--h", "2"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("takes only -o DIR and --save, not '--h'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(p.dir / "plan" / "trajectory.csv"));
  const CliRun noOut = runCli({"plan", p.file.string()});
  EXPECT_EQ(noOut.exitCode, 2) << noOut.err;
}

TEST(CliPlanProject, DamagedProjectIsBadInput)
{
  TempDir dir;
  std::ofstream(dir / "broken.spira") << "SPIRAPRJ but not really";
  const CliRun r = runCli({"plan", (dir / "broken.spira").string(), "-o", (dir / "plan").string()});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("broken.spira"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace spira::test
