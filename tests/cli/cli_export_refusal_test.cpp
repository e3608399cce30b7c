// An export refused because the cell cannot execute some points (unreachable, colliding,
// outside the joint limits) is an infeasible plan, exit 4, not bad input (3): the plan and the
// files are fine, the cell is not up to them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cell_variant.h"
#include "cli_runner.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

nlohmann::json readReport(const fs::path& dir)
{
  return nlohmann::json::parse(readBytes(dir / "report.json"));
}

// The KUKA cell with the part 1.5 m beyond its reach.
fs::path outOfReachCell(const fs::path& dir)
{
  return bundledCellVariant("kuka_kr16_2_table.cell", dir, [](nlohmann::json& c) {
    c["part"]["pose"]["xyz_mm"] = {3500, 0, 400};
  });
}

TEST(CliExportRefusal, UnreachablePointsMakeTheExportInfeasible)
{
  TempDir dir;
  const fs::path cell = outOfReachCell(dir.path());
  const fs::path plan = dir / "plan";
  const CliRun planned = runCli({"plan", cylinderPart(dir.path(), 50.0, 30.0).string(), "-o", plan.string(),
                                 "--cell", cell.string(), "--points-per-rev", "36", "--export", "krl"});
  EXPECT_EQ(planned.exitCode, 4) << planned.err << planned.out;
  EXPECT_NE(planned.err.find("unreachable"), std::string::npos) << planned.err;
  EXPECT_EQ(readReport(plan)["reachable"], false);

  const fs::path program = dir / "program";
  const CliRun exported = runCli({"export", plan.string(), "--format", "krl", "-o", program.string()});
  EXPECT_EQ(exported.exitCode, 4) << exported.err << exported.out;
  EXPECT_NE(exported.err.find("cannot be executed as planned"), std::string::npos) << exported.err;
  EXPECT_TRUE(!fs::exists(program) || fs::is_empty(program));
  // Forced, the same export is written.
  const CliRun forced =
      runCli({"export", plan.string(), "--format", "krl", "-o", program.string(), "--force"});
  EXPECT_EQ(forced.exitCode, 0) << forced.err << forced.out;
}

// Planning again into a folder replaces the whole set: a plan whose export is refused leaves no
// program of the previous plan beside it, and a folder whose files do not belong together (an
// older writer killed between two renames) is refused by export, naming the file.
TEST(CliExportRefusal, ARefusedExportLeavesNoProgramOfThePreviousPlan)
{
  TempDir dir;
  const fs::path part = cylinderPart(dir.path(), 50.0, 30.0);
  const fs::path plan = dir / "plan";
  const fs::path reachable = sourceDir() / "resources/cells/kuka_kr16_2_table.cell";
  const CliRun first = runCli({"plan", part.string(), "-o", plan.string(), "--cell", reachable.string(),
                               "--points-per-rev", "36", "--export", "krl"});
  ASSERT_EQ(first.exitCode, 0) << first.err << first.out;
  size_t programs = 0;
  for (const auto& e : fs::directory_iterator(plan)) programs += e.path().extension() == ".src";
  ASSERT_EQ(programs, 1u);

  const CliRun second =
      runCli({"plan", part.string(), "-o", plan.string(), "--cell", outOfReachCell(dir.path()).string(),
              "--points-per-rev", "36", "--export", "krl"});
  EXPECT_EQ(second.exitCode, 4) << second.err << second.out;
  for (const auto& e : fs::directory_iterator(plan))
    EXPECT_TRUE(e.path().extension() != ".src" && e.path().extension() != ".dat") << e.path();
  EXPECT_EQ(readReport(plan)["reachable"], false);

  std::string csv = readBytes(plan / "trajectory.csv");
  csv.back() = csv.back() == '\n' ? ' ' : '\n';
  writeBytes(plan / "trajectory.csv", csv);
  const CliRun mixed = runCli({"export", plan.string(), "--format", "krl", "-o", (dir / "program").string()});
  EXPECT_EQ(mixed.exitCode, 3) << mixed.err << mixed.out;
  EXPECT_NE(mixed.err.find("trajectory.csv"), std::string::npos) << mixed.err;
  EXPECT_NE(mixed.err.find("plan it again"), std::string::npos) << mixed.err;
}

}  // namespace
}  // namespace spira::test
