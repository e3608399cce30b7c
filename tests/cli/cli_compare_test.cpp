#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "planning/slanted_tube.h"
#include "spira/io/mesh_writers.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

struct Row {
  Vec3 p;
  double height = 0.0;
};

std::map<std::string, std::vector<Row>> readCompareCsv(const fs::path& file, std::string* header)
{
  std::ifstream in(file);
  std::getline(in, *header);
  std::map<std::string, std::vector<Row>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string strategy, cell;
    std::getline(s, strategy, ',');
    std::vector<double> v;
    while (std::getline(s, cell, ',')) v.push_back(std::stod(cell));
    EXPECT_EQ(v.size(), 4u) << line;
    if (v.size() == 4u) rows[strategy].push_back(Row{Vec3(v[0], v[1], v[2]), v[3]});
  }
  return rows;
}

const nlohmann::json* find(const nlohmann::json& report, const std::string& strategy)
{
  for (const auto& s : report["strategies"])
    if (s["strategy"] == strategy) return &s;
  return nullptr;
}

// Thesis Fig. 3.41 / V9 on a wall with a slanted top edge (generatrices 95 to 105 mm): CTPP
// modulates the deposit inside 2 mm +/- 10 % and ends on the edge; planar layers every 2 mm leave
// the edge anywhere from 0 to 2 mm above the last plane under it.
TEST(CliCompare, PlanarSlicingLeavesTheWindowWhereCtppStaysInside)
{
  TempDir dir;
  writeMesh(slantedTube(40.0, 100.0, 5.0, 120, 60), dir / "slanted.stl");
  const auto out = dir / "cmp";
  const CliRun r =
      runCli({"compare", (dir / "slanted.stl").string(), "-o", out.string(), "--points-per-rev", "120"});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  std::ifstream in(out / "compare.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_EQ(report["h"], 2.0);
  EXPECT_EQ(report["h_min"], 1.8);
  EXPECT_EQ(report["h_max"], 2.2);

  const nlohmann::json* iso = find(report, "isovalue");
  const nlohmann::json* planar = find(report, "planar_2.5d");
  ASSERT_TRUE(iso && planar);
  EXPECT_TRUE((*iso)["ran"].get<bool>());
  EXPECT_TRUE((*iso)["feasible"].get<bool>());
  EXPECT_EQ((*iso)["points_outside_window"], 0);
  EXPECT_GE((*iso)["deposit_min"].get<double>(), 1.8 - 0.01);
  EXPECT_LE((*iso)["deposit_max"].get<double>(), 2.2 + 0.01);
  EXPECT_NEAR((*iso)["generatrix_length_spread"].get<double>(), 10.0, 0.05);
  EXPECT_EQ((*iso)["n_paths"], 1);
  EXPECT_GT((*iso)["revolutions"].get<int>(), 40);
  EXPECT_TRUE((*planar)["ran"].get<bool>());
  EXPECT_FALSE((*planar)["feasible"].get<bool>());
  EXPECT_GT((*planar)["points_outside_window"].get<int>(), 0);
  EXPECT_LT((*planar)["deposit_min"].get<double>(), 0.5);
  EXPECT_TRUE((*planar)["generatrix_length_spread"].is_null());
  EXPECT_EQ((*planar)["revolutions"], 53);  // planes 2 .. 104 mm, then the top edge
  // Every registered decomposer is listed, ran or not, each with a reason when it did not.
  for (const auto& s : report["strategies"]) {
    EXPECT_TRUE(s.contains("runtime_s"));
    if (!s["ran"].get<bool>()) {
      EXPECT_FALSE(s["failure"].get<std::string>().empty());
    }
  }

  std::string header;
  const auto rows = readCompareCsv(out / "compare.csv", &header);
  EXPECT_EQ(header, "strategy,x,y,z,height");
  ASSERT_EQ(rows.at("isovalue").size(), (*iso)["n_points"].get<size_t>());
  ASSERT_EQ(rows.at("planar_2.5d").size(), (*planar)["n_points"].get<size_t>());
  // Planar points on the slanted edge need less than h_min where the edge is just above a plane.
  size_t low = 0;
  for (const Row& row : rows.at("planar_2.5d")) low += row.height < 1.8 - 0.01;
  EXPECT_EQ(static_cast<int>(low), (*planar)["points_outside_window"].get<int>());
}

// A strategy that cannot plan the part is listed with its reason; the others still run. When none
// plans it, the comparison is still written and the exit code says the part is infeasible.
TEST(CliCompare, AFailingStrategyIsListedNotAnError)
{
  TempDir dir;
  // Too short for the start-up and termination ramps of any CTPP spiral at h = 2 mm.
  writeMesh(slantedTube(40.0, 12.0, 0.0, 120, 6), dir / "short.stl");
  const auto out = dir / "cmp";
  const CliRun r = runCli({"compare", (dir / "short.stl").string(), "-o", out.string()});
  ASSERT_EQ(r.exitCode, 4) << r.err << r.out;
  EXPECT_NE(r.err.find("no strategy plans this part feasibly"), std::string::npos) << r.err;
  std::ifstream in(out / "compare.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  const nlohmann::json* iso = find(report, "isovalue");
  ASSERT_TRUE(iso);
  EXPECT_FALSE((*iso)["ran"].get<bool>());
  EXPECT_FALSE((*iso)["feasible"].get<bool>());
  EXPECT_NE((*iso)["failure"].get<std::string>().find("ramps"), std::string::npos) << (*iso)["failure"];
  EXPECT_TRUE((*iso)["deposit_min"].is_null());
  const nlohmann::json* planar = find(report, "planar_2.5d");
  ASSERT_TRUE(planar);
  EXPECT_TRUE((*planar)["ran"].get<bool>());
  EXPECT_TRUE((*planar)["feasible"].get<bool>());  // a straight wall: h everywhere
  EXPECT_NE(r.out.find("failed"), std::string::npos);
}

TEST(CliCompare, NeedsAnOutputFolder)
{
  const CliRun r = runCli({"compare", (sourceDir() / "resources" / "samples" / "cone.stl").string()});
  EXPECT_EQ(r.exitCode, 2) << r.err;
}

}  // namespace
}  // namespace spira::test
