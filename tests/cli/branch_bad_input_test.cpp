// spira-cli on parts the multi-branch planner and the geodesic decomposer cannot plan: a clear
// message and exit code 3 (bad input), never a hang.
#include <gtest/gtest.h>

#include <string>

#include "cli_runner.h"
#include "planning/y_tube.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

constexpr int kBadInput = 3;

// A trunk whose two arms part and join again above: a handle, so the part's branches form a loop,
// not a tree (its skeleton has a cycle).
TriangleMesh handlePart()
{
  const double r = 8.0;
  const Vec3 o(0, 0, 25), left(-20, 0, 45), right(20, 0, 45), join(0, 0, 65);
  auto implicit = [&](const Vec3& p) {
    double d = segmentDistance(p, Vec3(0, 0, -100), o);
    for (const auto& [a, b] : {std::pair<Vec3, Vec3>{o, left}, {left, join}, {o, right}, {right, join}})
      d = std::min(d, segmentDistance(p, a, b));
    d = std::min(d, segmentDistance(p, join, Vec3(0, 0, 200)));
    return d - r;
  };
  return marchingTetrahedra(implicit, Vec3(-32, -12, 0), 64, 24, 90, 1.0, 1.0);
}

TEST(CliBranchBadInput, APartWithAHandleIsRefusedWithExitCode3)
{
  TempDir dir;
  writeMesh(handlePart(), dir / "handle.stl");
  const CliRun r = runCli({"plan", (dir / "handle.stl").string(), "-o", (dir / "out").string()});
  EXPECT_EQ(r.exitCode, kBadInput) << r.err << r.out;
  EXPECT_NE(r.err.find("join again"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not a tree of branches"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "trajectory.csv"));
}

// Two tubes one above the other: no path on the surface joins the lower tube's base to the upper
// edge. The geodesic strategy (and any other) says so and exits with 3.
TEST(CliBranchBadInput, AnUpperEdgeThatCannotBeReachedIsBadInput)
{
  TempDir dir;
  TriangleMesh mesh = makeOpenCylinder(20, 20, 32, 5);
  const TriangleMesh upper = makeOpenCylinder(20, 20, 32, 5);
  const int offset = static_cast<int>(mesh.vertices.size());
  for (const Vec3& v : upper.vertices) mesh.vertices.push_back(v + Vec3(0, 0, 30));
  for (const Face& f : upper.faces) mesh.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  writeMesh(mesh, dir / "apart.stl");
  for (const char* strategy : {"geodesic", "isovalue"}) {
    SCOPED_TRACE(strategy);
    const CliRun r = runCli(
        {"plan", (dir / "apart.stl").string(), "-o", (dir / strategy).string(), "--strategy", strategy});
    EXPECT_EQ(r.exitCode, kBadInput) << r.err << r.out;
    EXPECT_FALSE(r.err.empty());
    EXPECT_FALSE(fs::exists(dir / strategy / "trajectory.csv"));
  }
}

// An upper edge shrunk to almost a point (a cone whose top radius is a hundredth of a millimetre):
// the last revolutions collapse onto it, so the plan is refused as infeasible (exit code 4) with
// the reason, and the report is still written for the user to look at.
// A needle-like top (0.01 mm radius): the last revolutions would pile onto themselves. Refused up
// front with the edge's length and what to do, by every strategy, without computing anything.
TEST(CliBranchBadInput, ADegenerateUpperEdgeIsRefusedWithItsLength)
{
  TempDir dir;
  writeMesh(makeOpenCone(20.0, 0.01, 30.0, 64, 20), dir / "spike.stl");
  for (const char* strategy : {"geodesic", "isovalue", "envelope_projection"}) {
    SCOPED_TRACE(strategy);
    const CliRun r = runCli(
        {"plan", (dir / "spike.stl").string(), "-o", (dir / strategy).string(), "--strategy", strategy});
    EXPECT_EQ(r.exitCode, 3) << r.err << r.out;
    EXPECT_NE(r.err.find("upper free edge is only 0.06 mm around"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("shorter than one bead ring (16.34 mm)"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / strategy / "trajectory.csv"));
  }
}

}  // namespace
}  // namespace spira::test
