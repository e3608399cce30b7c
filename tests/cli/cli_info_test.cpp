#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
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

TEST(CliInfo, OpenCylinderSampleHasTwoLoopsOfTheRightLength)
{
  const CliRun r = runCli({"info", sample("open_cylinder.stl").string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["part_class"], "open");
  EXPECT_EQ(j["component_count"], 1);
  ASSERT_EQ(j["boundary_loops"].size(), 2u);
  const double expected = 2.0 * kPi * 50.0;
  for (const auto& loop : j["boundary_loops"])
    EXPECT_NEAR(loop["length_mm"].get<double>(), expected, 1e-3 * expected);
  EXPECT_NEAR(j["boundary_loops"][0]["z_max_mm"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(j["boundary_loops"][1]["z_min_mm"].get<double>(), 100.0, 1e-9);
  EXPECT_TRUE(j["issues"].empty());
}

TEST(CliInfo, DomeIsClosedAndTextReportIsReadable)
{
  const CliRun r = runCli({"info", sample("dome.stl").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("Boundary loops: 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Part class: closed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("z 0 .. 60 mm"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(CliInfo, TimingReportsStages)
{
  const CliRun r = runCli({"info", sample("cone.stl").string(), "--timing", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& t = j["timings_s"];
  EXPECT_NEAR(t["total"].get<double>(),
              t["read"].get<double>() + t["weld"].get<double>() + t["validate"].get<double>(), 1e-9);
}

TEST(CliInfo, UnitFlagScalesTheMesh)
{
  const CliRun r = runCli({"info", sample("open_cylinder.stl").string(), "--json", "--unit", "cm"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["source_unit"], "cm");
  EXPECT_NEAR(j["bounds_mm"]["max"][2].get<double>(), 1000.0, 1e-9);
}

TEST(CliInfo, NonManifoldPartIsReportedWithPositions)
{
  TempDir dir;
  // Two triangles sharing only vertex (0,0,0): a bow-tie with one non-manifold vertex.
  writeBytes(dir / "bowtie.stl",
             "solid b\n"
             "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
             "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex -1 0 0\nvertex 0 -1 0\nendloop\nendfacet\n"
             "endsolid b\n");
  const CliRun r = runCli({"info", (dir / "bowtie.stl").string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["issues"].size(), 1u) << j["issues"].dump();
  EXPECT_EQ(j["issues"][0]["kind"], "non_manifold_vertex");
  EXPECT_EQ(j["issues"][0]["count"], 1);
  EXPECT_FALSE(j["plannable"].get<bool>());
}

// A single triangle or a flat strip is a clean mesh but no part: nothing rises from its edge.
TEST(CliInfo, EdgeOnlyPartsAreNotCalledPlannable)
{
  TempDir dir;
  writeBytes(
      dir / "triangle.stl",
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 100 0 0\nvertex 0 100 0\nendloop\n"
      "endfacet\nendsolid t\n");
  TriangleMesh strip;
  for (int i = 0; i <= 4; ++i) {
    strip.vertices.push_back(Vec3(50.0 * i, 0, 0));
    strip.vertices.push_back(Vec3(50.0 * i, 5, 0));
  }
  for (int i = 0; i < 4; ++i) {
    strip.faces.push_back({2 * i, 2 * i + 2, 2 * i + 3});
    strip.faces.push_back({2 * i, 2 * i + 3, 2 * i + 1});
  }
  writeMesh(strip, dir / "strip.stl", MeshFileFormat::StlBinary);
  for (const char* name : {"triangle.stl", "strip.stl"}) {
    const CliRun r = runCli({"info", (dir / name).string(), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["part_class"], "unsupported") << name;
    EXPECT_TRUE(j["issues"].empty()) << name << j["issues"].dump();
    EXPECT_FALSE(j["plannable"].get<bool>()) << name;
    const CliRun text = runCli({"info", (dir / name).string()});
    EXPECT_NE(text.out.find("Plannable: no, the part has no wall"), std::string::npos) << text.out;
    const CliRun plan = runCli({"plan", (dir / name).string(), "-o", (dir / "plan").string()});
    EXPECT_EQ(plan.exitCode, 3) << name << plan.err;
  }
}

TEST(CliExitCodes, BadInputIsThreeWithOneLineCauseAndHint)
{
  TempDir dir;
  writeBytes(dir / "empty.stl", "");
  writeBytes(dir / "short.stl", std::string(84, '\0') + "xx");
  writeBytes(dir / "part.dwg", "whatever");
  const std::vector<std::vector<std::string>> cases = {
      {"info", (dir / "missing.stl").string()}, {"info", (dir / "empty.stl").string()},
      {"info", (dir / "short.stl").string()},   {"info", (dir / "part.dwg").string()},
      {"info", dir.path().string() + "/"},
  };
  for (const auto& c : cases) {
    const CliRun r = runCli(c);
    EXPECT_EQ(r.exitCode, 3) << c[1] << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
    EXPECT_NE(r.err.find(" ("), std::string::npos) << "no hint: " << r.err;
  }
}

TEST(CliExitCodes, UsageErrorsAreTwo)
{
  EXPECT_EQ(runCli({"frobnicate"}).exitCode, 2);
  EXPECT_EQ(runCli({"info"}).exitCode, 2);
  EXPECT_EQ(runCli({"info", sample("dome.stl").string(), "--no-such-flag"}).exitCode, 2);
  EXPECT_EQ(runCli({"info", "a.stl", "b.stl"}).exitCode, 2);
  EXPECT_EQ(runCli({}).exitCode, 2);
  // A flag's value that is not one of its choices is a usage error like a missing value.
  const CliRun unit = runCli({"info", sample("dome.stl").string(), "--unit", "furlong"});
  EXPECT_EQ(unit.exitCode, 2) << unit.err;
  EXPECT_NE(unit.err.find("'furlong' is not an allowed choice (use one of: mm, cm, m, in)"),
            std::string::npos);
  const CliRun v = runCli({"--version"});
  EXPECT_EQ(v.exitCode, 0);
  EXPECT_EQ(v.out.rfind("spira-cli ", 0), 0u);
}

}  // namespace
}  // namespace spira::test
