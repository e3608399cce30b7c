// spira-cli export on a saved .spira project: the program equals the one exported from the plan
// folder, a project without a trajectory is refused, the plain CSV export, bad output folders.
#include <gtest/gtest.h>

#include <memory>

#include "cli_runner.h"
#include "program_text.h"
#include "spira/document/document.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/planning/trajectory_csv_reader.h"
#include "spira/robotcell/cell_file.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

fs::path resource(const std::string& sub)
{
  return sourceDir() / "resources" / sub;
}

size_t count(const std::string& text, const std::string& what)
{
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The text without comment lines (the header names the source and the date).
std::string withoutComments(const std::string& text)
{
  std::string out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(";", 0) != 0 && line.rfind("&", 0) != 0) out += line + "\n";
  return out;
}

// A plan made by the CLI on the KUKA table cell, then saved as a project by the document model.
struct PlannedProject {
  TempDir dir;
  fs::path planDir, project;
  Trajectory trajectory;

  PlannedProject()
  {
    planDir = dir / "plan";
    const CliRun r = runCli({"plan", resource("samples/open_cylinder.stl").string(), "-o", planDir.string(),
                             "--cell", resource("cells/kuka_kr16_2_table.cell").string(), "--points-per-rev",
                             "90", "--keep-collisions"});
    EXPECT_EQ(r.exitCode, 0) << r.err << r.out;
    trajectory = readTrajectoryCsv(planDir / "trajectory.csv");
    Document doc;
    Part part;
    part.name = "open_cylinder.stl";
    part.sourcePath = "open_cylinder.stl";
    part.mesh = std::make_shared<const TriangleMesh>(makeOpenCylinder(50.0, 100.0, 90, 50));
    doc.setPart(part);
    doc.setCell(readCellFile(resource("cells/kuka_kr16_2_table.cell")));
    doc.setProcess(std::make_shared<const Trajectory>(trajectory));
    project = dir / "wall.spira";
    doc.saveAs(project);
  }
};

PlannedProject& planned()
{
  static PlannedProject p;
  return p;
}

TEST(ExportProject, KrlFromTheProjectEqualsKrlFromThePlanFolder)
{
  PlannedProject& p = planned();
  const fs::path fromProject = p.dir / "krl_project", fromPlan = p.dir / "krl_plan";
  const CliRun a = runCli({"export", p.project.string(), "--format", "krl", "-o", fromProject.string(),
                           "--program-name", "wall"});
  ASSERT_EQ(a.exitCode, 0) << a.err << a.out;
  const CliRun b = runCli(
      {"export", p.planDir.string(), "--format", "krl", "-o", fromPlan.string(), "--program-name", "wall"});
  ASSERT_EQ(b.exitCode, 0) << b.err << b.out;
  const std::string src = readBytes(fromProject / "wall.src"), dat = readBytes(fromProject / "wall.dat");
  EXPECT_NE(src.find("; cell: KUKA KR 16-2 on a fixed table"), std::string::npos);
  EXPECT_NE(src.find("; part: open_cylinder.stl"), std::string::npos);
  EXPECT_EQ(count(src, "$OUT[1]=TRUE"), 1u);
  EXPECT_EQ(count(src, "$OUT[1]=FALSE"), 1u);
  EXPECT_EQ(count(src, "LIN XP"), count(dat, "DECL E6POS XP"));
  EXPECT_GT(count(dat, "DECL E6POS XP"), 100u);
  // Same cell, same trajectory, same settings: the same motion, target for target.
  EXPECT_EQ(withoutComments(src), withoutComments(readBytes(fromPlan / "wall.src")));
  EXPECT_EQ(withoutComments(dat), withoutComments(readBytes(fromPlan / "wall.dat")));
  EXPECT_EQ(e6posStatusValues(dat).size(), 1u);
}

TEST(ExportProject, CellFlagOverridesTheProjectCell)
{
  PlannedProject& p = planned();
  const fs::path out = p.dir / "tp_project";
  const CliRun r = runCli({"export", p.project.string(), "--format", "fanuc_tp", "-o", out.string(), "--cell",
                           resource("cells/fanuc_m20ia_positioner.cell").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const std::string ls = readBytes(out / "SPIRA_PART.ls");
  EXPECT_EQ(count(ls, ":  Arc Start["), 1u);
  EXPECT_EQ(count(ls, ":  Arc End["), 1u);
  EXPECT_NE(ls.find("DEFAULT_GROUP\t= 1,1,*,*,*;"), std::string::npos);  // the positioner cell's GP2
}

TEST(ExportProject, CsvWritesThePlannedTrajectoryAndItsJoints)
{
  PlannedProject& p = planned();
  const fs::path out = p.dir / "csv";
  const CliRun r = runCli({"export", p.project.string(), "--format", "csv", "-o", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const Trajectory back = readTrajectoryCsv(out / "trajectory.csv");
  ASSERT_EQ(back.size(), p.trajectory.size());
  for (size_t i = 0; i < back.size(); i += 7)
    EXPECT_LT((back.points[i].position - p.trajectory.points[i].position).norm(), 1e-6) << i;
  EXPECT_EQ(count(readBytes(out / "joints.csv"), "\n"), p.trajectory.size() + 1);  // header + one per point
}

TEST(ExportProject, AProjectWithoutATrajectoryIsRefusedWithAHint)
{
  TempDir dir;
  Document doc;
  doc.setCell(readCellFile(resource("cells/kuka_kr16_2_table.cell")));
  doc.saveAs(dir / "empty.spira");
  const CliRun r =
      runCli({"export", (dir / "empty.spira").string(), "--format", "krl", "-o", (dir / "out").string()});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("no planned trajectory"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("plan it first"), std::string::npos) << r.err;
  EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out"));
}

TEST(ExportProject, AnUnwritableOutputFolderFailsBeforeAnythingIsWritten)
{
  PlannedProject& p = planned();
  writeBytes(p.dir / "a_file", "x");
  const CliRun r =
      runCli({"export", p.project.string(), "--format", "krl", "-o", (p.dir / "a_file" / "sub").string()});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(fs::is_regular_file(p.dir / "a_file"));
  EXPECT_EQ(readBytes(p.dir / "a_file"), "x");
  const CliRun noFile = runCli(
      {"export", (p.dir / "missing.spira").string(), "--format", "krl", "-o", (p.dir / "never").string()});
  EXPECT_EQ(noFile.exitCode, 3) << noFile.err;
  EXPECT_FALSE(fs::exists(p.dir / "never"));
}

}  // namespace
}  // namespace spira::test
