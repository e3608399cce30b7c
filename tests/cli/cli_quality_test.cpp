// spira-cli scan-compare --plan --at and resume: the quality indices of the open cylinder built 8 % short
// (trajectory 1, process 0.92), grown by 1 % (global 1 - 0.5 / h), planned dropped onto the plate or as
// a thin-walled solid (measured where the plan runs); flags that do not go together are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

constexpr int kUsage = 2, kBadInput = 3;

nlohmann::json readJson(const fs::path& file)
{
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

std::vector<std::vector<std::string>> csvRows(const fs::path& file)
{
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(csvCells(line));
  return rows;
}

// Plans `part` into dir/plan and returns its number of points.
size_t plan(const TempDir& dir, const std::string& part, const std::vector<std::string>& flags = {})
{
  std::vector<std::string> args = {"plan", part, "-o", (dir / "plan").string()};
  args.insert(args.end(), flags.begin(), flags.end());
  const CliRun r = runCli(args);
  EXPECT_EQ(r.exitCode, 0) << r.err << r.out;
  return csvRows(dir / "plan" / "trajectory.csv").size() - 1;
}

// The wall of dir/plan built to `at` 8 % short on every bead, scanned into dir/wall.ply.
void buildShort(const TempDir& dir, size_t at)
{
  const CliRun r = runCli({"scan-sim", (dir / "plan").string(), "--at", std::to_string(at), "--error",
                           "uniform:-8%", "-o", (dir / "wall.ply").string(), "--noise", "0.05"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
}

CliRun compare(const TempDir& dir, const std::string& part, const std::string& scan, size_t at,
               const std::string& out)
{
  return runCli({"scan-compare", part, scan, "-o", (dir / out).string(), "--plan", (dir / "plan").string(),
                 "--at", std::to_string(at), "--no-align", "--outlier-stddev", "0"});
}

TEST(CliScanQuality, TheCylinderBuiltShortAndGrownHasItsAnalyticIndices)
{
  TempDir dir;
  ASSERT_EQ(runCli({"sample", "open-cylinder", "-o", (dir / "cylinder.stl").string()}).exitCode, 0);
  const std::string cylinder = (dir / "cylinder.stl").string();
  const size_t points = plan(dir, cylinder);
  const size_t at = points / 2;
  buildShort(dir, at);
  const CliRun r = compare(dir, cylinder, (dir / "wall.ply").string(), at, "short");
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("quality indices (1 = as planned; means): trajectory 1, process 0.9"),
            std::string::npos)
      << r.out;
  const nlohmann::json q = readJson(dir / "short" / "deviation.json")["quality_indices"];
  // The plan runs on the cylinder's facets.
  EXPECT_NEAR(q["trajectory"]["mean"].get<double>(), 1.0, 1e-6);
  EXPECT_NEAR(q["trajectory"]["min"].get<double>(), 1.0, 1e-6);
  EXPECT_EQ(q["trajectory"]["count"].get<size_t>(), at);
  EXPECT_NEAR(q["process"]["mean"].get<double>(), 0.92, 0.005);
  EXPECT_EQ(q["process"]["below_0_9"].get<double>(), 0.0);
  const auto rows = csvRows(dir / "short" / "quality.csv");
  ASSERT_EQ(rows.size(), at + 1);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"index", "x", "y", "z", "h_mm", "trajectory_index",
                                               "process_index", "scan_deviation_mm"}));
  size_t edge = 0;
  for (size_t k = 1; k < rows.size(); ++k) edge += rows[k].size() >= 7 && !rows[k][6].empty();
  EXPECT_EQ(edge, q["process"]["count"].get<size_t>());
  EXPECT_EQ(csvRows(dir / "short" / "deviation.csv")[0].back(), "global_index");

  // resume measures the same edge from the same points: the same process index.
  const CliRun rest = runCli({"resume", (dir / "plan").string(), "--scan", (dir / "wall.ply").string(),
                              "--at", std::to_string(at), "-o", (dir / "rest").string()});
  ASSERT_EQ(rest.exitCode, 0) << rest.err << rest.out;
  const nlohmann::json p = readJson(dir / "rest" / "report.json")["process_index"];
  EXPECT_NEAR(p["mean"].get<double>(), q["process"]["mean"].get<double>(), 1e-12);
  EXPECT_NEAR(p["min"].get<double>(), q["process"]["min"].get<double>(), 1e-12);
  EXPECT_NE(rest.out.find("process index of the wall as built"), std::string::npos) << rest.out;

  // Grown by 1 % about its base, the whole part built: the wall 0.5 mm outside, I_g = 1 - 0.5 / h with
  // the plan's mean bead height (0.001 lower from the points above the nominal top, measured to it).
  ASSERT_EQ(
      runCli({"scan-sim", cylinder, "-o", (dir / "grown.ply").string(), "--scale", "1.01", "--noise", "0.01"})
          .exitCode,
      0);
  const CliRun grown = compare(dir, cylinder, (dir / "grown.ply").string(), points, "grown");
  ASSERT_EQ(grown.exitCode, 0) << grown.err << grown.out;
  double h = 0.0;
  const auto plan = csvRows(dir / "plan" / "trajectory.csv");
  for (size_t k = 1; k < plan.size(); ++k) h += std::stod(plan[k][15]);
  h /= double(plan.size() - 1);
  const nlohmann::json g = readJson(dir / "grown" / "deviation.json")["quality_indices"];
  std::printf(
      "cylinder: I_t %.9f, I_p %.5f (0.92), resume's %.5f; grown 1 %%: I_g %.5f (1 - 0.5 / %.5f = %.5f)\n",
      q["trajectory"]["mean"].get<double>(), q["process"]["mean"].get<double>(), p["mean"].get<double>(),
      g["global"]["mean"].get<double>(), h, 1.0 - 0.5 / h);
  EXPECT_NEAR(g["global"]["mean"].get<double>(), 1.0 - 0.5 / h, 0.002);
  EXPECT_EQ(g["global"]["count"].get<size_t>(), csvRows(dir / "grown" / "deviation.csv").size() - 1);
  // Seen along the path: each plan point of the wall's middle (z 20 to 80) has the scan 0.5 mm outside.
  size_t middle = 0;
  double worst = 0.0, sum = 0.0;
  for (const auto& row : csvRows(dir / "grown" / "quality.csv")) {
    if (row[0] == "index" || row.size() < 8 || row[7].empty()) continue;
    const double z = std::stod(row[3]);
    if (z < 20.0 || z > 80.0) continue;
    ++middle;
    worst = std::max(worst, std::abs(std::stod(row[7]) - 0.5));
    sum += std::stod(row[7]);
  }
  std::printf(
      "grown 1 %%: %zu plan points of the middle, scan deviation along them %.4f mm on average, each within "
      "%.4f mm of 0.5\n",
      middle, sum / double(std::max<size_t>(middle, 1)), worst);
  EXPECT_GT(middle, points / 2);
  EXPECT_NEAR(sum / double(middle), 0.5, 0.005);
  EXPECT_LT(worst, 0.05);  // the few scan points of each plan point, at 0.01 mm noise, on 120 facets
}

// Planned with --drop, the plan stands 10 mm lower than the part's file: the part is moved there.
TEST(CliScanQuality, APartDroppedOntoThePlateIsComparedWhereThePlanPutIt)
{
  TempDir dir;
  TriangleMesh raised = makeOpenCylinder(50.0, 100.0, 120, 50);
  for (Vec3& v : raised.vertices) v.z() += 10.0;
  writeMesh(raised, dir / "raised.stl");
  const size_t at = plan(dir, (dir / "raised.stl").string(), {"--drop"}) / 2;
  EXPECT_EQ(readJson(dir / "plan" / "report.json")["dropped_mm"].get<double>(), -10.0);
  buildShort(dir, at);
  const CliRun r = compare(dir, (dir / "raised.stl").string(), (dir / "wall.ply").string(), at, "cmp");
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("moved the part -10 mm along z"), std::string::npos) << r.out;
  const nlohmann::json q = readJson(dir / "cmp" / "deviation.json")["quality_indices"];
  EXPECT_NEAR(q["trajectory"]["min"].get<double>(), 1.0, 1e-6);
  EXPECT_NEAR(q["process"]["mean"].get<double>(), 0.92, 0.005);

  // The plan of another part lies off this one: refused, nothing written.
  const std::string dome = (sourceDir() / "resources/samples/dome.stl").string();
  const CliRun other = compare(dir, dome, (dir / "wall.ply").string(), at, "other");
  EXPECT_EQ(other.exitCode, kBadInput) << other.out;
  EXPECT_NE(other.err.find("a bead height or more off"), std::string::npos) << other.err;
  EXPECT_FALSE(fs::exists(dir / "other" / "deviation.json"));
}

// A tube 2 mm thick is planned on its mid-surface, 1 mm inside each skin: measured against the skins
// its trajectory index would be 1 - 1 / 2; against the mid-surface the plan runs on, 1 (within
// 0.0001 mm: the mid-surface is offset from the skins again for the comparison).
TEST(CliScanQuality, AThinWalledSolidsPlanIsMeasuredOnItsMidSurface)
{
  TempDir dir;
  writeMesh(makeTubeSolid(51.0, 49.0, 60.0, 120, 30), dir / "tube.stl");
  const size_t at = plan(dir, (dir / "tube.stl").string()) / 2;
  buildShort(dir, at);
  const CliRun r = compare(dir, (dir / "tube.stl").string(), (dir / "wall.ply").string(), at, "cmp");
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const nlohmann::json q = readJson(dir / "cmp" / "deviation.json")["quality_indices"];
  EXPECT_NEAR(q["trajectory"]["min"].get<double>(), 1.0, 1e-4 / 1.8);
  EXPECT_NEAR(q["process"]["mean"].get<double>(), 0.92, 0.005);
}

TEST(CliScanQuality, FlagsThatDoNotGoTogetherAreRefused)
{
  TempDir dir;
  const std::string dome = (sourceDir() / "resources/samples/dome.stl").string();
  const size_t points = plan(dir, dome);
  buildShort(dir, points / 2);
  const std::string scan = (dir / "wall.ply").string(), planDir = (dir / "plan").string();
  const auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"scan-compare", dome, scan, "-o", (dir / "out").string(), "--no-align"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runCli(args);
  };
  const CliRun atAlone = run({"--at", "100"});
  EXPECT_EQ(atAlone.exitCode, kUsage);
  EXPECT_NE(atAlone.err.find("--at needs --plan"), std::string::npos) << atAlone.err;
  const CliRun planAlone = run({"--plan", planDir});
  EXPECT_EQ(planAlone.exitCode, kUsage);
  EXPECT_NE(planAlone.err.find("--plan needs --at INDEX"), std::string::npos) << planAlone.err;
  const CliRun bead = run({"--bead-width", "6"});
  EXPECT_EQ(bead.exitCode, kUsage);
  EXPECT_NE(bead.err.find("--bead-width is for the quality indices"), std::string::npos) << bead.err;
  EXPECT_EQ(run({"--plan", planDir, "--at", "half"}).exitCode, kUsage);
  const CliRun beyond = run({"--plan", planDir, "--at", std::to_string(points + 1)});
  EXPECT_EQ(beyond.exitCode, kBadInput);
  EXPECT_NE(beyond.err.find("outside the plan's " + std::to_string(points) + " points"), std::string::npos)
      << beyond.err;
  EXPECT_EQ(run({"--plan", planDir, "--at", "0"}).exitCode, kBadInput);
  const CliRun noPlan = run({"--plan", (dir / "none").string(), "--at", "10"});
  EXPECT_EQ(noPlan.exitCode, kBadInput);
  EXPECT_NE(noPlan.err.find("is not a plan folder"), std::string::npos) << noPlan.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "deviation.json"));
}

}  // namespace
}  // namespace spira::test
