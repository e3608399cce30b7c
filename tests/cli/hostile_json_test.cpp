// JSON read from disk (a cell, a plan folder's report.json) that is malformed or has a field of the
// wrong type is bad input (exit 3) with a message naming the file, the place and what was found,
// never the JSON library's own text or an internal error (exit 1).
#include <gtest/gtest.h>

#include <memory>

#include <nlohmann/json.hpp>

#include "cell_variant.h"
#include "cli_runner.h"
#include "spira/base/output_set.h"
#include "spira/document/document.h"
#include "spira/planning/trajectory_csv_reader.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

bool has(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

// One plan folder shared by the tests (a small cylinder, no cell): each test copies it and edits
// its report.json.
class HostileReport : public ::testing::Test {
 protected:
  static void SetUpTestSuite()
  {
    dir_ = new TempDir;
    const CliRun r = runCli({"plan", cylinderPart(dir_->path(), 30.0, 50.0).string(), "-o",
                             (*dir_ / "plan").string(), "--points-per-rev", "36"});
    ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  }
  static void TearDownTestSuite()
  {
    delete dir_;
    dir_ = nullptr;
  }

  // A copy of the plan folder with report.json's `key` set to `value`, without the set's manifest
  // (which would refuse the edited file as a whole), as an older Spira wrote plan folders: then
  // the report itself is read field by field.
  fs::path editedPlan(const std::string& key, const nlohmann::json& value)
  {
    const fs::path plan = tmp_ / "plan";
    fs::copy(*dir_ / "plan", plan);
    nlohmann::json report = nlohmann::json::parse(readBytes(plan / "report.json"));
    report[key] = value;
    writeBytes(plan / "report.json", report.dump(2));
    fs::remove(plan / kOutputManifest);
    return plan;
  }

  CliRun exportPlan(const fs::path& plan)
  {
    return runCli({"export", plan.string(), "--format", "krl", "-o", (tmp_ / "program").string()});
  }

  TempDir tmp_;
  static TempDir* dir_;
};

TempDir* HostileReport::dir_ = nullptr;

TEST_F(HostileReport, WrongTypedRevolutionCountNamesFileAndField)
{
  const fs::path plan = editedPlan("n_revolutions", "x");
  const CliRun r = exportPlan(plan);
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(has(r.err, (plan / "report.json").string() +
                             ": field 'n_revolutions' must be a whole number, found the string \"x\""))
      << r.err;
  EXPECT_FALSE(has(r.err, "json.exception")) << r.err;
}

TEST_F(HostileReport, NumericCellFileIsRefused)
{
  const CliRun r = exportPlan(editedPlan("cell_file", 5));
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(has(r.err, "field 'cell_file' must be a string, found the number 5")) << r.err;
}

TEST_F(HostileReport, StringHeightIsRefused)
{
  const CliRun r = exportPlan(editedPlan("height_max", "tall"));
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(has(r.err, "field 'height_max' must be a number, found the string \"tall\"")) << r.err;
}

// A verdict that is not true or false must not let an infeasible plan through as if it had none.
TEST_F(HostileReport, VerdictOfTheWrongTypeIsRefusedNotIgnored)
{
  const CliRun r = exportPlan(editedPlan("feasible", "no"));
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(has(r.err, "field 'feasible' must be true or false, found the string \"no\"")) << r.err;
  if (fs::exists(tmp_ / "program")) {
    for (const auto& e : fs::directory_iterator(tmp_ / "program"))
      EXPECT_NE(e.path().extension(), ".src") << "a program was written from a damaged report";
  }
}

TEST_F(HostileReport, InfeasibleVerdictQuotesTheDepositCheckSummary)
{
  const fs::path plan = editedPlan("feasible", false);
  nlohmann::json report = nlohmann::json::parse(readBytes(plan / "report.json"));
  report["deposit_check"]["summary"] = "3 points rejected: 2 thin, 1 jump";
  writeBytes(plan / "report.json", report.dump(2));
  const CliRun r = exportPlan(plan);
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_TRUE(has(r.err, "the plan is infeasible: 3 points rejected: 2 thin, 1 jump")) << r.err;
}

TEST_F(HostileReport, DepositCheckThatIsNotAnObjectIsRefused)
{
  const CliRun r = exportPlan(editedPlan("deposit_check", 7));
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(has(r.err, "field 'deposit_check' must be an object, found the number 7")) << r.err;
}

TEST_F(HostileReport, HugeStringIsClippedInTheMessage)
{
  const CliRun r = exportPlan(editedPlan("n_revolutions", std::string(100000, 'y')));
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(has(r.err, "found the string \"" + std::string(60, 'y') + "...\"")) << r.err;
  EXPECT_LT(r.err.size(), 400u) << r.err.size();
}

TEST_F(HostileReport, SyntaxErrorGivesLineAndColumn)
{
  const fs::path plan = tmp_ / "plan";
  fs::copy(*dir_ / "plan", plan);
  writeBytes(plan / "report.json", "{\n  \"part\": \"dome\",\n  \"n_revolutions\": 3 4\n}\n");
  fs::remove(plan / kOutputManifest);
  const CliRun r = exportPlan(plan);
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(has(r.err, "report.json, line 3, column 22: unexpected '4'")) << r.err;
  EXPECT_FALSE(has(r.err, "json.exception")) << r.err;
}

TEST_F(HostileReport, ProjectsStoredReportOfTheWrongTypeIsNamed)
{
  Document doc;
  const auto path = std::make_shared<const Trajectory>(readTrajectoryCsv(*dir_ / "plan" / "trajectory.csv"));
  doc.setSpiral(path, std::make_shared<const SpiralStageReport>());
  doc.setProcess(path, std::make_shared<const ProcessStageReport>());
  const fs::path project = tmp_ / "wall.spira";
  doc.saveAs(project);
  // The spiral stage's report holds the plan's figures (report.json's top level).
  nlohmann::json j = projectJsonOf(readBytes(project));
  j["results"]["reports"]["spiral"]["payload"]["path_length"] = "long";
  writeBytes(project, projectBytesOf(j));
  const CliRun r = runCli({"export", project.string(), "--format", "krl", "-o", (tmp_ / "program").string()});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(has(r.err,
                  "wall.spira: project results spiral report: field 'path_length' must be a number, found "
                  "the string \"long\""))
      << r.err;
}

TEST(HostileCell, NumberBeyondDoubleRangeIsBadInputWithItsPlace)
{
  TempDir dir;
  const fs::path cell = bundledCellVariant("kuka_kr16_2_table.cell", dir.path(), [](nlohmann::json& c) {
    c["part"]["pose"]["xyz_mm"] = {123456789, 0, 400};
  });
  std::string text = readBytes(cell);
  const size_t at = text.find("123456789");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 9, "1e999");
  writeBytes(cell, text);
  size_t line = 1, column = 1;
  for (size_t i = 0; i < at; ++i) text[i] == '\n' ? (++line, column = 1) : ++column;

  const CliRun r = runCli({"kin", cell.string(), "--fk", "0", "0", "0", "0", "0", "0"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(has(r.err, "line " + std::to_string(line) + ", column " + std::to_string(column) +
                             ": the number 1e999 is beyond the range of a double"))
      << r.err;
  EXPECT_FALSE(has(r.err, "internal error")) << r.err;
}

}  // namespace
}  // namespace spira::test
