// A part with no wall in it (a single triangle, faces collapsed to a line) is never reported as a
// part Spira can plan: 'info' classes it unsupported with the reason, 'plan' refuses it (exit 3).
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

std::string asciiStl(const std::vector<std::array<double, 9>>& triangles)
{
  std::string s = "solid t\n";
  for (const auto& t : triangles) {
    s += "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k)
      s += "vertex " + std::to_string(t[3 * k]) + " " + std::to_string(t[3 * k + 1]) + " " +
           std::to_string(t[3 * k + 2]) + "\n";
    s += "endloop\nendfacet\n";
  }
  return s + "endsolid t\n";
}

void expectNoWall(const std::vector<std::array<double, 9>>& triangles, const std::string& reason)
{
  TempDir dir;
  writeBytes(dir / "part.stl", asciiStl(triangles));
  const CliRun info = runCli({"info", (dir / "part.stl").string(), "--json"});
  ASSERT_EQ(info.exitCode, 0) << info.err;
  const nlohmann::json j = nlohmann::json::parse(info.out);
  EXPECT_EQ(j["part_class"], "unsupported");
  EXPECT_NE(j["class_reason"].get<std::string>().find(reason), std::string::npos) << j["class_reason"];
  const CliRun plan = runCli({"plan", (dir / "part.stl").string(), "-o", (dir / "out").string()});
  EXPECT_EQ(plan.exitCode, 3) << plan.err << plan.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "trajectory.csv"));
}

TEST(HostileMesh, SingleTriangleIsRefused)
{
  expectNoWall({{0, 0, 0, 10, 0, 0, 0, 0, 10}}, "every vertex lies on the part's one boundary edge");
}

TEST(HostileMesh, FacesCollapsedToALineAreRefused)
{
  expectNoWall({{0, 0, 0, 10, 0, 0, 20, 0, 0}, {0, 0, 0, 20, 0, 0, 30, 0, 0}}, "all 2 faces are degenerate");
}

}  // namespace
}  // namespace spira::test
