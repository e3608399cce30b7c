// spira-cli scan-sim and scan-compare: a simulated scan of a real part, moved and noised, is registered
// back and measured; scans in other units, far from the part, or missing are refused with exit 3 and
// nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/triangle_mesh.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

constexpr int kBadInput = 3;

std::string junction()
{
  return (sourceDir() / "tests/data/real/junction_waam_mm.stl").string();
}

nlohmann::json readJson(const fs::path& file)
{
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

size_t lines(const fs::path& file)
{
  std::ifstream in(file);
  size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

TEST(CliScan, ASimulatedScanIsAlignedAndMeasured)
{
  TempDir dir;
  const CliRun sim = runCli({"scan-sim", junction(), "-o", (dir / "scan.ply").string(), "--spacing", "1",
                             "--noise", "0.05", "--move", "3,-2,1,1,-1,2", "--seed", "5"});
  ASSERT_EQ(sim.exitCode, 0) << sim.err;
  const CliRun r =
      runCli({"scan-compare", junction(), (dir / "scan.ply").string(), "-o", (dir / "cmp").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const nlohmann::json j = readJson(dir / "cmp" / "deviation.json");
  // Moved by 3,-2,1 mm and turned by (1, -1, 2) deg about the part's centre: the fit turns it back by
  // the same angle, sqrt(1 + 1 + 4) deg for such small turns to within 0.01 deg.
  EXPECT_NEAR(j["alignment"]["rotation_deg"].get<double>(), std::sqrt(6.0), 0.01);
  EXPECT_LT(j["alignment"]["rms_mm"].get<double>(), 0.05);
  EXPECT_GT(j["alignment"]["inlier_fraction"].get<double>(), 0.99);
  // Aligned, the scan lies on the part within its noise.
  EXPECT_NEAR(j["deviation"]["mean_mm"].get<double>(), 0.0, 0.005);
  EXPECT_NEAR(j["deviation"]["rms_mm"].get<double>(), 0.05, 0.005);
  const size_t points = j["points"].get<size_t>();
  EXPECT_GT(points, 90000u);
  EXPECT_EQ(lines(dir / "cmp" / "deviation.csv"), points + 1);
  EXPECT_TRUE(fs::exists(dir / "cmp" / "aligned_scan.ply"));
  EXPECT_NE(r.out.find("deviation from the part"), std::string::npos) << r.out;

  // The scan taken in the part's frame is measured where it lies: 3 mm off in places.
  const CliRun raw = runCli(
      {"scan-compare", junction(), (dir / "scan.ply").string(), "-o", (dir / "raw").string(), "--no-align"});
  ASSERT_EQ(raw.exitCode, 0) << raw.err;
  EXPECT_GT(readJson(dir / "raw" / "deviation.json")["deviation"]["rms_mm"].get<double>(), 1.0);
}

TEST(CliScan, BadScansAreRefusedWithTheChangeThatWorks)
{
  TempDir dir;
  // Written in inches: 25.4 times too small in mm.
  ASSERT_EQ(runCli({"scan-sim", junction(), "-o", (dir / "inch.xyz").string(), "--spacing", "2", "--scale",
                    std::to_string(1.0 / 25.4)})
                .exitCode,
            0);
  const CliRun inch =
      runCli({"scan-compare", junction(), (dir / "inch.xyz").string(), "-o", (dir / "a").string()});
  EXPECT_EQ(inch.exitCode, kBadInput) << inch.out;
  EXPECT_NE(inch.err.find("likely in inches"), std::string::npos) << inch.err;
  EXPECT_NE(inch.err.find("--scan-scale"), std::string::npos) << inch.err;
  EXPECT_FALSE(fs::exists(dir / "a" / "deviation.json"));

  ASSERT_EQ(runCli({"scan-sim", junction(), "-o", (dir / "far.ply").string(), "--spacing", "2", "--move",
                    "400,0,0"})
                .exitCode,
            0);
  const CliRun far =
      runCli({"scan-compare", junction(), (dir / "far.ply").string(), "-o", (dir / "b").string()});
  EXPECT_EQ(far.exitCode, kBadInput) << far.out;
  EXPECT_NE(far.err.find("does not overlap the part"), std::string::npos) << far.err;
  EXPECT_FALSE(fs::exists(dir / "b" / "deviation.json"));

  // The same scan with three places picked on the part and on it (0.3 mm off by hand) is brought back.
  std::ofstream(dir / "pairs.csv") << "part_x,part_y,part_z,scan_x,scan_y,scan_z\n0,0,0,400.3,0,0\n"
                                      "60,0,0,460,0.2,0\n0,60,30,400,59.8,30.3\n";
  const CliRun picked = runCli({"scan-compare", junction(), (dir / "far.ply").string(), "-o",
                                (dir / "b").string(), "--pairs", (dir / "pairs.csv").string()});
  ASSERT_EQ(picked.exitCode, 0) << picked.err;
  const nlohmann::json pj = readJson(dir / "b" / "deviation.json");
  EXPECT_NEAR(pj["alignment"]["translation_mm"].get<double>(), 400.0, 0.02);
  EXPECT_LT(pj["alignment"]["rotation_deg"].get<double>(), 0.02);
  EXPECT_GT(pj["picked_pairs"]["rms_mm"].get<double>(), 0.05);  // the picks were rough; ICP was not
  EXPECT_LT(pj["alignment"]["rms_mm"].get<double>(), 0.05);
  std::ofstream(dir / "two.csv") << "0,0,0,400,0,0\n60,0,0,460,0,0\n";
  const CliRun two = runCli({"scan-compare", junction(), (dir / "far.ply").string(), "-o",
                             (dir / "e").string(), "--pairs", (dir / "two.csv").string()});
  EXPECT_EQ(two.exitCode, kBadInput);
  EXPECT_NE(two.err.find("needs three pairs, 2 given"), std::string::npos) << two.err;
  EXPECT_FALSE(fs::exists(dir / "e" / "deviation.json"));

  const CliRun missing =
      runCli({"scan-compare", junction(), (dir / "none.ply").string(), "-o", (dir / "c").string()});
  EXPECT_EQ(missing.exitCode, kBadInput) << missing.out;
  EXPECT_NE(missing.err.find("none.ply"), std::string::npos) << missing.err;

  std::ofstream(dir / "bad.xyz") << "1 2 3\n4 x 6\n";
  const CliRun bad =
      runCli({"scan-compare", junction(), (dir / "bad.xyz").string(), "-o", (dir / "d").string()});
  EXPECT_EQ(bad.exitCode, kBadInput);
  EXPECT_NE(bad.err.find("'bad.xyz' line 2: 'x' is not a number"), std::string::npos) << bad.err;

  EXPECT_EQ(runCli({"scan-compare", junction(), (dir / "far.ply").string()}).exitCode, 2);  // no -o
  EXPECT_EQ(runCli({"scan-sim", junction(), "-o", (dir / "s.ply").string(), "--move", "1,2"}).exitCode, 2);
}

// A nominal flat-bottomed cylinder on a plate that is bowed and tilted (0.3 sin(x / 25) + 0.002 y mm),
// planned on a simulated scan of the plate (noise 0.02 mm): the first revolution's beads are laid to the
// plate as it is, each within 0.05 mm of its true distance to it, and the plan is feasible.
TEST(CliScan, APlanOnAScannedWarpedPlateMeasuresItsFirstBeadsFromTheScan)
{
  TempDir dir;
  const auto plate = [](double x, double y) { return 0.3 * std::sin(x / 25.0) + 0.002 * y; };
  TriangleMesh mesh;
  const int n = 161;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -80.0 + 160.0 * i / (n - 1), y = -80.0 + 160.0 * j / (n - 1);
      mesh.vertices.emplace_back(x, y, plate(x, y));
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i;
      mesh.faces.push_back({a, a + 1, a + n + 1});
      mesh.faces.push_back({a, a + n + 1, a + n});
    }
  writeMesh(mesh, dir / "plate.stl");
  ASSERT_EQ(runCli({"sample", "open-cylinder", "-o", (dir / "cylinder.stl").string()}).exitCode, 0);
  ASSERT_EQ(runCli({"scan-sim", (dir / "plate.stl").string(), "-o", (dir / "plate.ply").string(), "--noise",
                    "0.02", "--spacing", "0.7"})
                .exitCode,
            0);
  const CliRun r = runCli({"plan", (dir / "cylinder.stl").string(), "--substrate-scan",
                           (dir / "plate.ply").string(), "-o", (dir / "plan").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  std::ifstream in(dir / "plan" / "trajectory.csv");
  std::string line;
  std::getline(in, line);
  double worst = 0.0;
  size_t first = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> c = csvCells(line);
    if (std::stoi(c[13]) != 0) break;  // rev
    const double x = std::stod(c[1]), y = std::stod(c[2]), z = std::stod(c[3]), h = std::stod(c[15]);
    worst = std::max(worst, std::abs(h - (z - plate(x, y))));
    ++first;
  }
  std::printf("first revolution on the scanned plate: %zu beads, each within %.4f mm of its true height\n",
              first, worst);
  EXPECT_GT(first, 100u);
  EXPECT_LT(worst, 0.05);
  // The plate's own mesh gives the same plan a surface to stand on; naming both is a usage error.
  const CliRun flat = runCli({"plan", (dir / "cylinder.stl").string(), "--substrate",
                              (dir / "plate.stl").string(), "-o", (dir / "mesh").string()});
  EXPECT_EQ(flat.exitCode, 0) << flat.out;
  EXPECT_EQ(runCli({"plan", (dir / "cylinder.stl").string(), "--substrate-scan", (dir / "plate.ply").string(),
                    "--substrate", (dir / "plate.stl").string(), "-o", (dir / "x").string()})
                .exitCode,
            2);
}

}  // namespace
}  // namespace spira::test
