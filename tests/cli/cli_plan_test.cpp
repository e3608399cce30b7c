#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "planning/slanted_tube.h"
#include "planning/y_tube.h"
#include "spira/base/units.h"
#include "spira/io/mesh_writers.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

fs::path sample(const std::string& name)
{
  return sourceDir() / "resources" / "samples" / name;
}

struct CsvRow {
  Vec3 p, n, t, b;
  int rev = 0, gen = 0;
  double height = 0, ts = 0, wfs = 0;
  int arc = 0;
  int path = 0;
};

std::vector<CsvRow> readTrajectory(const fs::path& file, std::string* header)
{
  std::ifstream in(file);
  std::getline(in, *header);
  std::vector<CsvRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string cell;
    std::vector<double> v;
    while (std::getline(s, cell, ',')) v.push_back(std::stod(cell));
    EXPECT_EQ(v.size(), 20u);
    if (v.size() != 20u) continue;
    CsvRow r;
    r.p = Vec3(v[1], v[2], v[3]);
    r.n = Vec3(v[4], v[5], v[6]);
    r.t = Vec3(v[7], v[8], v[9]);
    r.b = Vec3(v[10], v[11], v[12]);
    r.rev = static_cast<int>(v[13]);
    r.gen = static_cast<int>(v[14]);
    r.height = v[15];
    r.ts = v[16];
    r.wfs = v[17];
    r.arc = static_cast<int>(v[18]);
    r.path = static_cast<int>(v[19]);
    rows.push_back(r);
  }
  return rows;
}

nlohmann::json readJson(const fs::path& file)
{
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

TEST(CliPlan, CylinderWritesTheContractedFiles)
{
  TempDir dir;
  const CliRun r = runCli({"plan", sample("open_cylinder.stl").string(), "-o", dir.path().string(), "--h",
                           "1", "--points-per-rev", "180"});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const auto report = readJson(dir / "report.json");
  EXPECT_EQ(report["part_type"], "open");
  EXPECT_EQ(report["strategy"], "isovalue");
  EXPECT_EQ(report["n_generatrices"], 180);
  // The plugin's full id names the same strategy, and the report writes its one name.
  TempDir full;
  ASSERT_EQ(runCli({"plan", sample("open_cylinder.stl").string(), "-o", full.path().string(), "--h", "1",
                    "--points-per-rev", "180", "--strategy", "decomposer.isovalue"})
                .exitCode,
            0);
  EXPECT_EQ(readJson(full / "report.json")["strategy"], "isovalue");
  EXPECT_EQ(report["n_startup_revolutions"], 6);
  EXPECT_TRUE(report["feasible"].get<bool>());
  EXPECT_EQ(report["violations"], 0);
  EXPECT_TRUE(report["closure_point"].is_null());
  for (const char* key :
       {"generatrix_length_min", "generatrix_length_max", "n_revolutions", "n_points", "height_min",
        "height_max", "height_mean", "path_length", "build_time_s", "timings_s", "warnings"})
    EXPECT_TRUE(report.contains(key)) << key;
  EXPECT_NEAR(report["generatrix_length_min"].get<double>(), 100.0, 0.2);
  EXPECT_NEAR(report["height_mean"].get<double>(), 1.0, 0.01);

  std::string header;
  const auto rows = readTrajectory(dir / "trajectory.csv", &header);
  EXPECT_EQ(header, "index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc,path");
  EXPECT_EQ(report["n_paths"], 1);
  ASSERT_EQ(rows.size(), report["n_points"].get<size_t>());
  double zMax = 0.0;
  for (const auto& row : rows) {
    zMax = std::max(zMax, row.p.z());
    EXPECT_NEAR(row.n.norm(), 1.0, 1e-9);
    EXPECT_NEAR(row.b.norm(), 1.0, 1e-9);
    EXPECT_NEAR(row.n.cross(row.t).dot(row.b), 1.0, 1e-9);  // b = n x t
    EXPECT_NEAR(row.wfs, 2.3, 1e-9);                        // synergic: constant wire feed, m/min
    EXPECT_EQ(row.arc, 1);
    EXPECT_EQ(row.path, 0);
    EXPECT_GE(row.height, 0.9 - 0.005);  // the whole path, ramps included, in the window
    EXPECT_LE(row.height, 1.1 + 0.005);
  }
  EXPECT_NEAR(zMax, 100.0, 1e-6);
}

TEST(CliPlan, HeightsRecomputedFromTheCsvMatchTheHeightColumn)
{
  TempDir dir;
  const CliRun r =
      runCli({"plan", sample("cone.stl").string(), "-o", dir.path().string(), "--points-per-rev", "120"});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  std::string header;
  const auto rows = readTrajectory(dir / "trajectory.csv", &header);
  // h = d cos(theta): the step along the generatrix since the previous revolution, projected on b.
  std::map<std::pair<int, int>, Vec3> at;
  for (const auto& row : rows) at[{row.rev, row.gen}] = row.p;
  size_t checked = 0;
  for (const auto& row : rows) {
    auto prev = at.find({row.rev - 1, row.gen});
    if (prev == at.end()) continue;
    const double h = (row.p - prev->second).dot(row.b);
    EXPECT_NEAR(h, row.height, 1e-6) << "rev " << row.rev << " gen " << row.gen;
    ++checked;
  }
  EXPECT_GT(checked, rows.size() / 2);
  // Synergic mode: the travel speed is in phase opposition with the deposit.
  const auto report = readJson(dir / "report.json");
  double tsAtMin = 0, tsAtMax = 0, hMin = 1e9, hMax = 0;
  for (const auto& row : rows) {
    if (row.height < hMin) hMin = row.height, tsAtMin = row.ts;
    if (row.height > hMax) hMax = row.height, tsAtMax = row.ts;
  }
  EXPECT_GT(tsAtMin, tsAtMax);
}

// A closed part end to end with the defaults (h = 2 mm +/- 10 %, bead width 5.2 mm): every deposit
// of the path, start-up, termination and closure point included, lies in the window; the rings
// narrower than pi x bead width are folded into the closure point, which is reached once, last.
TEST(CliPlan, DomeIsFeasibleEverywhereAndEndsAtTheClosurePoint)
{
  TempDir dir;
  const CliRun r =
      runCli({"plan", sample("dome.stl").string(), "-o", dir.path().string(), "--points-per-rev", "90"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto report = readJson(dir / "report.json");
  EXPECT_EQ(report["part_type"], "closed");
  EXPECT_TRUE(report["feasible"].get<bool>());
  EXPECT_EQ(report["violations"], 0);
  ASSERT_TRUE(report["closure_point"].is_array());
  const Vec3 c(report["closure_point"][0], report["closure_point"][1], report["closure_point"][2]);
  EXPECT_LT((c - Vec3(0, 0, 60)).norm(), 0.5);
  std::string header;
  const auto rows = readTrajectory(dir / "trajectory.csv", &header);
  ASSERT_GT(rows.size(), 90u);
  EXPECT_LT((rows.back().p - c).norm(), 1e-6);
  const double tol = 0.005 * 2.0;
  size_t atClosure = 0;
  for (const auto& row : rows) {
    EXPECT_GE(row.height, 1.8 - tol) << "rev " << row.rev << " gen " << row.gen;
    EXPECT_LE(row.height, 2.2 + tol) << "rev " << row.rev << " gen " << row.gen;
    EXPECT_EQ(row.arc, 1);
    atClosure += (row.p - c).norm() < 1e-6;
  }
  EXPECT_EQ(atClosure, 1u);
  // The last ring is at least pi x 5.2 mm around (radius >= half the bead width) and the ring
  // before it was folded, so the gap left to the pole (about the ring's radius on the flat top) is
  // under half a bead width plus one step.
  double ring = 0.0;
  for (size_t q = rows.size() - 90; q + 1 < rows.size(); ++q) ring += (rows[q].p - rows[q - 1].p).norm();
  EXPECT_GE(ring, kPi * 5.2 * 0.99);
  const double gap = report["closure_gap"].get<double>();
  const auto& ringStart = rows[rows.size() - 1 - 90];  // generatrix 0, where the gap is measured
  ASSERT_EQ(ringStart.gen, 0);
  const double radius = (ringStart.p - c).head<2>().norm();
  EXPECT_NEAR(gap, radius, 0.1 * gap);
  EXPECT_LT(gap, 5.2 / 2.0 + 2.2 * 1.05);
}

TEST(CliPlan, TooDifferentGeneratricesAreInfeasibleWithTheReportWritten)
{
  TempDir dir;
  writeMesh(slantedTube(40.0, 100.0, 20.0, 120, 60), dir / "slanted.stl");
  const auto out = dir / "plan";
  const CliRun r =
      runCli({"plan", (dir / "slanted.stl").string(), "-o", out.string(), "--points-per-rev", "120"});
  EXPECT_EQ(r.exitCode, 4) << r.err << r.out;
  const auto report = readJson(out / "report.json");
  EXPECT_FALSE(report["feasible"].get<bool>());
  EXPECT_GT(report["violations"].get<int>(), 0);
  EXPECT_TRUE(fs::exists(out / "trajectory.csv"));
  EXPECT_NE(r.out.find("INFEASIBLE"), std::string::npos);
}

// A strategy that refuses a part names the one that should work; Spira plans that one too and,
// when it does not plan the part either (the corpus's honeycomb vase), says so rather than leave
// advice nobody checked.
TEST(CliPlan, ARefusalsAdviceThatDoesNotPlanSaysWhatItWasTriedWith)
{
  TempDir dir;
  const CliRun r = runCli({"plan", (sourceDir() / "tests/data/real/vase_honeycomb_wall.stl").string(), "-o",
                           (dir / "plan").string(), "--strategy", "geodesic"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("use --strategy isovalue"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tried: use the isovalue strategy: "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("planned and checked feasible"), std::string::npos) << r.err;
}

// A Y-shaped tube (three free edges, refused before multi-branch planning): three sub-paths in
// build order, trunk first, numbered in the path column, each an unbroken spiral.
TEST(CliPlan, YTubeIsPlannedAsSubPathsTrunkFirst)
{
  TempDir dir;
  YTube y;
  y.top = 150.0;
  y.cell = 1.5;
  writeMesh(y.mesh(), dir / "y.stl");
  const auto out = dir / "plan";
  const CliRun r = runCli({"plan", (dir / "y.stl").string(), "-o", out.string(), "--points-per-rev", "120"});
  // Its crotch cannot be laid bead on bead (tests/planning/junction_test.cpp): the advice says
  // where it is and why no setting plans it, not to make the walls rise more evenly.
  ASSERT_EQ(r.exitCode, 4) << r.err << r.out;
  EXPECT_NE(r.out.find("lie around the junction's crotch at (0.2, 0.0, 52.0) mm"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("saddle of the part's height"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("rise more evenly"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("multi-branch part"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("3 sub-paths"), std::string::npos) << r.out;
  const auto report = readJson(out / "report.json");
  EXPECT_EQ(report["part_type"], "multi_branch");
  EXPECT_NE(report["advice"]["cause"].get<std::string>().find("crotch"), std::string::npos);
  ASSERT_EQ(report["n_paths"], 3);
  std::string header;
  const auto rows = readTrajectory(out / "trajectory.csv", &header);
  ASSERT_EQ(rows.size(), report["n_points"].get<size_t>());
  std::vector<size_t> count(3, 0);
  for (size_t i = 0; i < rows.size(); ++i) {
    ASSERT_GE(rows[i].path, 0);
    ASSERT_LT(rows[i].path, 3);
    ++count[static_cast<size_t>(rows[i].path)];
    if (i == 0) continue;
    ASSERT_GE(rows[i].path, rows[i - 1].path);  // sub-paths one after the other
    if (rows[i].path == rows[i - 1].path) {
      EXPECT_LT((rows[i].p - rows[i - 1].p).norm(), 3.0) << "row " << i;
    }
  }
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(count[k], report["paths"][k]["n_points"].get<size_t>());
    EXPECT_EQ(report["paths"][k]["role"], k == 0 ? "trunk" : "branch");
  }
  EXPECT_LT(rows.front().p.z(), 2.2);  // the trunk starts on the substrate
  EXPECT_NEAR(rows.back().p.z(), 150.0, 1e-6);
}

TEST(CliPlan, BadSettingsAreRejectedBeforeAnythingIsWritten)
{
  TempDir dir;
  writeBytes(dir / "nonmono.csv", "height_mm,travel_speed_mm_s\n1.8,3.0\n2.0,3.5\n2.2,2.5\n");
  const std::string part = sample("open_cylinder.stl").string();
  // A flag's value outside its range is a usage error (2); values that do not fit together, or a bad
  // file, are bad input (3).
  const std::vector<std::pair<std::vector<std::string>, int>> cases = {
      {{"--h-min", "2.2", "--h-max", "1.8"}, 3},
      {{"--h", "3", "--h-min", "1.8", "--h-max", "2.2"}, 3},
      {{"--wfs", "-1"}, 2},
      {{"--ts", "0"}, 2},
      {{"--calibration", (dir / "nonmono.csv").string()}, 3},
      {{"--calibration", (dir / "missing.csv").string()}, 3},
      {{"--strategy", "nonexistent"}, 3},
  };
  for (const auto& [extra, exitCode] : cases) {
    const auto out = dir / "out";
    std::vector<std::string> args = {"plan", part, "-o", out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliRun r = runCli(args);
    EXPECT_EQ(r.exitCode, exitCode) << extra[0] << ": " << r.err;
    EXPECT_FALSE(fs::exists(out / "report.json")) << extra[0];
    EXPECT_FALSE(fs::exists(out / "trajectory.csv")) << extra[0];
    EXPECT_NE(r.err.find(" ("), std::string::npos) << "no hint: " << r.err;
  }
}

TEST(CliField, WritesCsvAndVtp)
{
  TempDir dir;
  const CliRun csv = runCli(
      {"field", sample("open_cylinder.stl").string(), "--kind", "harmonic", "-o", (dir / "h.csv").string()});
  ASSERT_EQ(csv.exitCode, 0) << csv.err;
  std::ifstream in(dir / "h.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "vertex,x,y,z,value");
  size_t rows = 0;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string cell;
    std::vector<double> v;
    while (std::getline(s, cell, ',')) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 5u);
    EXPECT_NEAR(v[4], v[3] / 100.0, 1e-6);  // harmonic field of a straight tube is z / H
    ++rows;
  }
  EXPECT_EQ(rows, 8007u);
  const CliRun vtp =
      runCli({"field", sample("dome.stl").string(), "--kind", "geodesic", "-o", (dir / "g.vtp").string()});
  ASSERT_EQ(vtp.exitCode, 0) << vtp.err;
  const std::string text = readBytes(dir / "g.vtp");
  EXPECT_NE(text.find("<VTKFile type=\"PolyData\""), std::string::npos);
  EXPECT_NE(text.find("NumberOfPoints=\"8837\""), std::string::npos);
  EXPECT_EQ(
      runCli({"field", sample("dome.stl").string(), "--kind", "harmonic", "-o", (dir / "x.csv").string()})
          .exitCode,
      3);
  EXPECT_EQ(
      runCli({"field", sample("dome.stl").string(), "--sources", "99999999", "-o", (dir / "x.csv").string()})
          .exitCode,
      3);
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
}

}  // namespace
}  // namespace spira::test
