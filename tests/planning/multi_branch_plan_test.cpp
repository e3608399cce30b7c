#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include <nlohmann/json.hpp>

#include "builtin_plugins.h"
#include "planning/y_tube.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/path/spiral_builder.h"
#include "spira/pipeline/plan_records.h"
#include "spira/planning/plan_files.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/planner.h"
#include "spira/planning/trajectory_csv_reader.h"
#include "spira/plugin/plugin_registry.h"

namespace spira::test {
namespace {

PlanOutput plan(const TriangleMesh& mesh, int pointsPerRev)
{
  const MeshReport report = validateMesh(mesh);
  PlanRequest request(mesh, report);
  request.params["decomposer.isovalue"].set("points_per_rev", std::int64_t{pointsPerRev});
  NullProgress progress;
  return planPart(builtinRegistry(), request, progress);
}

// A Y tube tall enough for every arm to hold its start-up and termination ramps.
const PlanOutput& yPlan()
{
  static const PlanOutput p = [] {
    YTube y;
    y.top = 150.0;
    y.cell = 1.5;
    return plan(y.mesh(), 120);
  }();
  return p;
}

// A path is continuous when no segment is longer than the local step: the spacing of the points
// around its revolution plus one layer's rise (what a seam climbs), with 25 % to spare. A closed
// sub-part's last segment reaches its closure point across the gap the last ring leaves, at most
// half a bead plus one step (the spiral builder's guarantee).
void expectContinuous(const Trajectory& t, size_t first, size_t count, double hMax, bool closed = false)
{
  if (closed) {
    const double last = (t.points[first + count - 1].position - t.points[first + count - 2].position).norm();
    EXPECT_LT(last, 5.2 / 2.0 + hMax * 1.05);
    --count;
  }
  std::map<int, double> revolutionLength;
  std::map<int, int> revolutionPoints;
  for (size_t q = first + 1; q < first + count; ++q)
    if (t.points[q].revolution == t.points[q - 1].revolution) {
      revolutionLength[t.points[q].revolution] += (t.points[q].position - t.points[q - 1].position).norm();
      ++revolutionPoints[t.points[q].revolution];
    }
  size_t checked = 0;
  for (size_t q = first + 1; q < first + count; ++q) {
    const int rev = t.points[q - 1].revolution;
    if (!revolutionPoints.count(rev)) continue;  // a lone closure point
    const double spacing = revolutionLength[rev] / revolutionPoints[rev];
    const double jump = (t.points[q].position - t.points[q - 1].position).norm();
    EXPECT_LE(jump, 1.25 * (spacing + hMax)) << "point " << q << " rev " << rev;
    ++checked;
  }
  EXPECT_GT(checked, count / 2);
}

TEST(MultiBranchPlan, YTubeIsPlannedAsThreeSubPathsTrunkFirst)
{
  const PlanOutput& p = yPlan();
  ASSERT_EQ(p.paths.size(), 3u);
  ASSERT_TRUE(p.branching);
  EXPECT_EQ(p.branching->saddles.size(), 1u);
  EXPECT_EQ(p.fieldKind, "geodesic_distance");
  const Trajectory& t = p.spiral.trajectory;
  ASSERT_EQ(t.size(), p.spiral.report.nPoints);
  size_t next = 0, revolutions = 0;
  for (size_t k = 0; k < 3; ++k) {
    const PathSummary& s = p.paths[k];
    EXPECT_EQ(s.path, static_cast<int>(k));
    EXPECT_EQ(s.firstPoint, next);
    EXPECT_EQ(s.pointCount, s.spiral.nPoints);
    EXPECT_EQ(s.parent, k == 0 ? -1 : 0);
    EXPECT_EQ(s.trunk, k == 0);
    EXPECT_EQ(s.partClass, PartClass::Open);
    EXPECT_EQ(s.generatrices, 120u);
    for (size_t q = s.firstPoint; q < s.firstPoint + s.pointCount; ++q) {
      ASSERT_EQ(t.points[q].path, static_cast<int>(k));
      EXPECT_TRUE(t.points[q].arcOn);  // one arc per sub-path: it stops where the path index changes
    }
    expectContinuous(t, s.firstPoint, s.pointCount, 2.2);
    next += s.pointCount;
    revolutions += static_cast<size_t>(s.spiral.nRevolutions);
  }
  EXPECT_EQ(next, t.size());
  EXPECT_EQ(static_cast<size_t>(p.spiral.report.nRevolutions), revolutions);
  // The trunk starts on the substrate and climbs to the crotch; each arm starts at the crotch
  // height and rises on its own side to the top of the part (z = 150).
  const PathSummary& trunk = p.paths[0];
  EXPECT_LT(t.points[0].position.z(), 2.2);
  double trunkTop = 0.0;
  for (size_t q = 0; q < trunk.pointCount; ++q) trunkTop = std::max(trunkTop, t.points[q].position.z());
  EXPECT_LT(trunkTop, YTube().saddle().z() + 6.0);
  for (size_t k : {1, 2}) {
    const PathSummary& arm = p.paths[k];
    const TrajectoryPoint& start = t.points[arm.firstPoint];
    const TrajectoryPoint& end = t.points[arm.firstPoint + arm.pointCount - 1];
    EXPECT_GT(start.position.z(), 40.0);
    EXPECT_NEAR(end.position.z(), 150.0, 1e-6);
    EXPECT_EQ(end.position.x() > 0, k == 2);
    EXPECT_GT(arm.baseLevel, p.branching->saddles[0].trunkTop);
  }
  // Reports add up: lengths and times summed, violations re-indexed into the whole path.
  double length = 0.0, time = 0.0;
  size_t violations = 0;
  for (const PathSummary& s : p.paths) {
    length += s.spiral.pathLength;
    time += s.process.buildTime;
    violations += s.spiral.violations.size();
  }
  EXPECT_NEAR(p.spiral.report.pathLength, length, 1e-9 * length);
  EXPECT_NEAR(p.process.buildTime, time, 1e-9 * time);
  ASSERT_EQ(p.spiral.report.violations.size(), violations);
  for (const HeightViolation& v : p.spiral.report.violations) {
    EXPECT_EQ(t.points[v.point].revolution, v.revolution);
    EXPECT_EQ(t.points[v.point].generatrix, v.generatrix);
  }
}

// Rows of sub-path k whose true deposit height lies outside the window [1.8, 2.2] mm widened by the
// planner's tolerance (0.5 % of h) and 0.005 mm of numerical slack.
size_t rowsOutsideWindow(const PlanOutput& p, size_t k)
{
  const PathSummary& s = p.paths[k];
  const double tol = 0.005 * 2.0 + 0.005;
  size_t outside = 0;
  for (size_t q = s.firstPoint; q < s.firstPoint + s.pointCount; ++q) {
    const double h = p.spiral.trajectory.points[q].height;
    outside += h < 1.8 - tol || h > 2.2 + tol;
  }
  return outside;
}

// The trunk ends on the saddle cut, a non-planar upper edge: its termination ramps are stretched
// per point by 1 / cos(theta), so every row lies in the window. The arms' planned rows outside it
// lie near the crotch, on their first revolutions, laid across the junction gap from the trunk's
// top; the deposit check's verdict on them is in junction_test.cpp.
TEST(MultiBranchPlan, YTubeRowsStayInTheWindow)
{
  const PlanOutput& p = yPlan();
  ASSERT_EQ(p.paths.size(), 3u);
  EXPECT_TRUE(p.paths[0].trunk);
  EXPECT_EQ(rowsOutsideWindow(p, 0), 0u);
  EXPECT_TRUE(p.paths[0].spiral.violations.empty());
  EXPECT_LE(rowsOutsideWindow(p, 1), 75u);
  EXPECT_LE(rowsOutsideWindow(p, 2), 75u);
}

TEST(MultiBranchPlan, ReportAndCsvCarryTheSubPaths)
{
  const PlanOutput& p = yPlan();
  const nlohmann::json j = planReportJson(p, "isovalue");
  EXPECT_EQ(j["part_type"], "multi_branch");
  EXPECT_EQ(j["n_paths"], 3);
  ASSERT_EQ(j["paths"].size(), 3u);
  EXPECT_EQ(j["paths"][0]["role"], "trunk");
  EXPECT_EQ(j["paths"][2]["role"], "branch");
  EXPECT_EQ(j["paths"][1]["first_point"], p.paths[1].firstPoint);
  EXPECT_NEAR(j["branching"]["junction_gap_mm"].get<double>(), p.branching->junctionGap, 1e-12);
  EXPECT_GT(j["branching"]["junction_gap_area_mm2"].get<double>(), 0.0);
  EXPECT_EQ(j["branching"]["saddles"][0]["branches"], 2);
  const Trajectory back = trajectoryFromCsv(trajectoryCsv(p.spiral.trajectory));
  ASSERT_EQ(back.size(), p.spiral.trajectory.size());
  for (size_t q = 0; q < back.size(); q += 97)
    EXPECT_EQ(back.points[q].path, p.spiral.trajectory.points[q].path);
  EXPECT_EQ(back.points.back().path, 2);
}

// Capped arms: the part has one free edge and its field's contours part into two loops, so the
// split is found from the field; each arm is a closed sub-part ending at its own closure point on
// its cap.
TEST(MultiBranchPlan, ClosedYEndsEachArmAtItsCap)
{
  YTube y;
  y.cell = 1.5;
  y.armRise = 70.0;
  y.top = 180.0;
  const PlanOutput p = plan(y.mesh(), 90);
  ASSERT_EQ(p.paths.size(), 3u);
  EXPECT_EQ(p.paths[0].partClass, PartClass::Open);
  for (size_t k : {1, 2}) {
    const PathSummary& arm = p.paths[k];
    EXPECT_EQ(arm.partClass, PartClass::Closed);
    ASSERT_TRUE(arm.hasClosure);
    // On the arm's round cap: the upper half of the sphere of radius r around the end of its axis.
    const Vec3 capCentre = y.armTip(k == 1 ? -1 : 1) - Vec3(0, 0, y.radius);
    EXPECT_NEAR((arm.closure.point - capCentre).norm(), y.radius, 0.3);
    EXPECT_GT(arm.closure.point.z(), capCentre.z() + 0.5 * y.radius);
    const TrajectoryPoint& last = p.spiral.trajectory.points[arm.firstPoint + arm.pointCount - 1];
    EXPECT_LT((last.position - arm.closure.point).norm(), 1e-6);
    expectContinuous(p.spiral.trajectory, arm.firstPoint, arm.pointCount, 2.2, true);
  }
}

// One open arm and one capped: two free edges, like a plain open tube, and a harmonic field with
// no saddle (it runs into the capped arm and back out); the geodesic distance from the base shows
// the split.
TEST(MultiBranchPlan, ACappedArmOnAnOpenPartIsFound)
{
  YTube y;
  y.cell = 1.5;
  y.top = 150.0;
  y.rightArmRise = 60.0;
  const TriangleMesh m = y.mesh();
  ASSERT_EQ(validateMesh(m).boundaryLoops.size(), 2u);
  const PlanOutput p = plan(m, 90);
  ASSERT_EQ(p.paths.size(), 3u);
  EXPECT_EQ(p.paths[0].partClass, PartClass::Open);
  EXPECT_EQ(p.paths[1].partClass, PartClass::Open);    // the arm at -x, open at the top
  EXPECT_EQ(p.paths[2].partClass, PartClass::Closed);  // the capped arm at +x
  const Trajectory& t = p.spiral.trajectory;
  for (const PathSummary& s : p.paths) expectContinuous(t, s.firstPoint, s.pointCount, 2.2, s.hasClosure);
  const Vec3 capCentre = y.armTip(1) - Vec3(0, 0, y.radius);
  EXPECT_NEAR((p.paths[2].closure.point - capCentre).norm(), y.radius, 0.3);
}

// A mono-branch part goes through the pipeline exactly as before: one path numbered 0, and the
// same trajectory, bit for bit, as the stages run by hand.
TEST(MultiBranchPlan, MonoBranchPlanIsTheStagesRunByHand)
{
  const TriangleMesh tube = makeOpenCylinder(40.0, 60.0, 96, 40);
  const PlanOutput p = plan(tube, 96);
  ASSERT_EQ(p.paths.size(), 1u);
  EXPECT_FALSE(p.branching);
  EXPECT_EQ(p.paths[0].pointCount, p.spiral.trajectory.size());
  for (const TrajectoryPoint& q : p.spiral.trajectory.points) EXPECT_EQ(q.path, 0);
  EXPECT_EQ(planReportJson(p, "isovalue")["n_paths"], 1);

  const PluginRegistry& registry = builtinRegistry();
  const DecomposerPlugin& decomposer = registry.decomposer("decomposer.isovalue");
  ParamSet params;
  params.set("points_per_rev", std::int64_t{96});
  DecomposeInput input{tube, PartClass::Open, p.topology.lower, p.topology.upper, std::nullopt, &p.field};
  NullProgress progress;
  const DecomposeResult d = decomposer.decompose(input, params.withDefaults(decomposer.schema()), progress);
  const PlanSections sections = readPlanSections({});
  SpiralResult s = buildSpiral(d.generatrices, sections.spiral, progress);
  applyProcess(s.trajectory, sections.process);
  EXPECT_TRUE(s.trajectory == p.spiral.trajectory);
}

}  // namespace
}  // namespace spira::test
