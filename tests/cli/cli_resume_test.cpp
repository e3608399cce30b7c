// spira-cli scan-sim PLAN_DIR and resume: the bundled dome built to half way 8 % short over its first
// 30 %, scanned in code and resumed, reaches its planned top; indices and scans that do not fit are
// refused with exit 3.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

constexpr int kBadInput = 3;

size_t rowsOf(const fs::path& csv)
{
  std::ifstream in(csv);
  size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n - 1;
}

TEST(CliResume, TheDomeBuiltShortIsResumedToItsTop)
{
  TempDir dir;
  const std::string dome = (sourceDir() / "resources/samples/dome.stl").string();
  ASSERT_EQ(runCli({"plan", dome, "-o", (dir / "plan").string()}).exitCode, 0);
  const size_t points = rowsOf(dir / "plan" / "trajectory.csv");
  const std::string at = std::to_string(points / 2);
  const CliRun sim = runCli({"scan-sim", (dir / "plan").string(), "--at", at, "--error", "uniform:-8%@30%",
                             "-o", (dir / "scan.ply").string(), "--noise", "0.05"});
  ASSERT_EQ(sim.exitCode, 0) << sim.err;
  const CliRun r = runCli({"resume", (dir / "plan").string(), "--scan", (dir / "scan.ply").string(), "--at",
                           at, "-o", (dir / "rest").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  std::ifstream in(dir / "rest" / "report.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_TRUE(j["reaches_top"].get<bool>());
  EXPECT_LT(j["leftover_mm"].get<double>(), 1e-9);
  EXPECT_EQ(j["edge"]["unmeasured"].get<size_t>(), 0u);
  // 8 % of the 30 % of the build laid short: over a millimetre at the top when resumed.
  EXPECT_GT(j["edge"]["shortfall_max_mm"].get<double>(), 1.0);
  ASSERT_EQ(points, 16201u);  // 45 revolutions of 360 points and the closure point
  // At 8,100 the generatrices carry 23 or 22 beads, of which the first 14 or 13
  // were laid short (before point 4,860): 1 - 0.08 x (180 x 14/23 + 14/22 + 179 x 13/22) / 360.
  const double counts = (180.0 * 14.0 / 23.0 + 14.0 / 22.0 + 179.0 * 13.0 / 22.0) / 360.0;
  EXPECT_NEAR(j["process_index"]["mean"].get<double>(), 1.0 - 0.08 * counts, 0.002);
  EXPECT_LE(j["height_max"].get<double>(), j["h_max"].get<double>() + 1e-9);
  EXPECT_EQ(rowsOf(dir / "rest" / "trajectory.csv"), points - points / 2);
  EXPECT_NE(r.out.find("made up within"), std::string::npos) << r.out;

  const CliRun beyond = runCli({"resume", (dir / "plan").string(), "--scan", (dir / "scan.ply").string(),
                                "--at", std::to_string(points + 5), "-o", (dir / "x").string()});
  EXPECT_EQ(beyond.exitCode, kBadInput);
  EXPECT_NE(beyond.err.find("outside the plan's"), std::string::npos) << beyond.err;
  // A scan of another place covers none of the top.
  ASSERT_EQ(
      runCli({"scan-sim", dome, "-o", (dir / "other.ply").string(), "--spacing", "3", "--move", "0,0,500"})
          .exitCode,
      0);
  const CliRun elsewhere = runCli({"resume", (dir / "plan").string(), "--scan", (dir / "other.ply").string(),
                                   "--at", at, "-o", (dir / "y").string()});
  EXPECT_EQ(elsewhere.exitCode, kBadInput);
  EXPECT_NE(elsewhere.err.find("covers none of the"), std::string::npos) << elsewhere.err;
  EXPECT_FALSE(fs::exists(dir / "y" / "report.json"));
  EXPECT_EQ(runCli({"resume", (dir / "plan").string(), "--at", at, "-o", (dir / "z").string()}).exitCode, 2);
}

// On the plan's robot cell the continuation is written as a program: one arc from the restart point.
TEST(CliResume, TheContinuationIsWrittenForThePlansCell)
{
  TempDir dir;
  const std::string dome = (sourceDir() / "resources/samples/dome.stl").string();
  const std::string cell = (sourceDir() / "resources/cells/fanuc_m20ia_positioner.cell").string();
  ASSERT_EQ(runCli({"plan", dome, "--cell", cell, "-o", (dir / "plan").string()}).exitCode, 0);
  const std::string at = std::to_string(rowsOf(dir / "plan" / "trajectory.csv") / 2);
  ASSERT_EQ(runCli({"scan-sim", (dir / "plan").string(), "--at", at, "--error", "uniform:-8%@30%", "-o",
                    (dir / "scan.ply").string()})
                .exitCode,
            0);
  const CliRun r = runCli({"resume", (dir / "plan").string(), "--scan", (dir / "scan.ply").string(), "--at",
                           at, "-o", (dir / "rest").string(), "--export", "fanuc_tp"});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  std::ifstream in(dir / "rest" / "SPIRA_PART.ls");
  size_t starts = 0, ends = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.find("!") != std::string::npos) continue;  // comments
    starts += line.find("Arc Start[") != std::string::npos;
    ends += line.find("Arc End[") != std::string::npos;
  }
  EXPECT_EQ(starts, 1u);
  EXPECT_EQ(ends, 1u);
}

}  // namespace
}  // namespace spira::test
