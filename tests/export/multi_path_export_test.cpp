// Plans with several sub-paths (multi-branch parts): one arc per sub-path, travel with the arc off
// between them at the safe height, no process output while the arc is off, one arm configuration
// inside each sub-path. Read back from the written files.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "builtin_plugins.h"
#include "export_test_data.h"
#include "krl_reader.h"
#include "spira/base/progress.h"
#include "spira/pipeline/export_job.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/robotcell/cell_file.h"
#include "support/test_support.h"
#include "tp_reader.h"

namespace spira {
namespace {

// Three helices one above the other, like a trunk and two arms: path 0 around the origin, paths 1
// and 2 beside each other above it.
Trajectory threePathPlan()
{
  Trajectory plan;
  const std::array<Vec3, 3> offsets{Vec3(0, 0, 0), Vec3(-25, 0, 8), Vec3(25, 0, 8)};
  for (int k = 0; k < 3; ++k) {
    Trajectory t = test::cylinderPlan(k == 0 ? 3 : 2, 36, k == 0 ? 30.0 : 12.0, 2.0);
    for (TrajectoryPoint& p : t.points) {
      p.position += offsets[static_cast<size_t>(k)];
      p.path = k;
      plan.points.push_back(p);
    }
  }
  return plan;
}

// Distance to the planned polyline of one sub-path. The smoothed path runs on the helix the
// polyline samples, up to the chords' sagitta (0.11 mm at 36 points per revolution of R 30) plus
// the chord tolerance (0.05 mm) away from it; the sub-paths are far farther apart.
constexpr double kOnPath = 0.2;

double distanceToPath(const Vec3& q, const Trajectory& plan, int path)
{
  double best = 1e9;
  for (size_t i = 1; i < plan.size(); ++i) {
    if (plan.points[i].path != path || plan.points[i - 1].path != path) continue;
    const Vec3 a = plan.points[i - 1].position, d = plan.points[i].position - a;
    const double u = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + u * d - q).norm());
  }
  return best;
}

double planTop(const Trajectory& plan)
{
  double z = -1e9;
  for (const auto& p : plan.points) z = std::max(z, p.position.z());
  return z;
}

ExportOutcome runJob(const std::string& id, const Trajectory& plan, const RobotCell* cell,
                     const std::filesystem::path& dir)
{
  ExportJob job;
  job.exporterId = id;
  job.exporterParams.set("process_command", std::string("speed_analog"));
  job.exporterParams.set("wfs_deadband", 0.0);
  job.prep.travelClearance = 25.0;
  job.cell = cell;
  job.header = test::testHeader();
  NullProgress progress;
  return exportTrajectory(builtinRegistry(), plan, job, dir, progress);
}

TEST(MultiPathExport, KrlHasOneArcPerSubPathAndNoOutputWhileTheArcIsOff)
{
  const Trajectory plan = threePathPlan();
  test::TempDir dir;
  const ExportOutcome out = runJob("export.krl", plan, nullptr, dir.path());
  EXPECT_EQ(out.subPaths, 3u);
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;

  bool arc = false;
  size_t ons = 0, offs = 0, ptp = 0, travelsAtHeight = 0;
  double travelTop = -1e9;  // highest target since the last arc went out
  int arcPath = -1;
  const double safe = planTop(plan) + 25.0;
  for (const test::KrlMove& m : run.moves) {
    bool onHere = false, offHere = false, wfsHere = false;
    for (const auto& t : m.triggers) {
      onHere = onHere || t.find("$OUT[1]=TRUE") != std::string::npos;
      offHere = offHere || t.find("$OUT[1]=FALSE") != std::string::npos;
      wfsHere = wfsHere || t.find("$ANOUT[") != std::string::npos;
      // Every trigger here is DISTANCE=0 (start of the move) but the arc-off one (its end).
      if (t.find("=FALSE") == std::string::npos) {
        EXPECT_NE(t.find("DISTANCE=0"), std::string::npos) << t;
      }
    }
    if (onHere) {
      EXPECT_FALSE(arc) << m.target;
      if (ons > 0 && travelTop > safe - 1e-3) ++travelsAtHeight;
      arc = true;
      ++ons;
      arcPath = -1;
    }
    EXPECT_TRUE(!wfsHere || arc) << "WFS output with the arc off at " << m.target;
    if (arc) {
      // Every target while the arc burns lies on one sub-path of the plan, the same for one arc.
      int nearest = -1;
      for (int k = 0; k < 3; ++k)
        if (distanceToPath(m.pose.xyz, plan, k) < kOnPath) nearest = k;
      EXPECT_GE(nearest, 0) << m.target;
      if (arcPath < 0) arcPath = nearest;
      EXPECT_EQ(nearest, arcPath) << m.target;
      EXPECT_EQ(arcPath, static_cast<int>(ons) - 1);  // sub-paths in build order
      EXPECT_EQ(m.motion, "LIN");
    } else if (m.motion == "PTP") {
      ++ptp;
    }
    if (!arc) travelTop = std::max(travelTop, m.pose.xyz.z());
    if (offHere) {
      EXPECT_TRUE(arc);
      arc = false;
      ++offs;
      travelTop = -1e9;
    }
  }
  EXPECT_EQ(ons, 3u);
  EXPECT_EQ(offs, 3u);
  EXPECT_FALSE(arc);
  EXPECT_EQ(ptp, 3u);              // the first move and one per change of sub-path
  EXPECT_EQ(travelsAtHeight, 2u);  // both travels rise to the safe height
}

TEST(MultiPathExport, TpHasOneArcStartAndEndPerSubPath)
{
  const Trajectory plan = threePathPlan();
  test::TempDir dir;
  runJob("export.fanuc_tp", plan, nullptr, dir.path());
  const test::TpRun run = test::runTp(dir.path(), "SPIRA_PART");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  ASSERT_EQ(run.arcStartAfter.size(), 3u);
  ASSERT_EQ(run.arcEndAfter.size(), 3u);
  for (size_t a = 0; a < 3; ++a) {
    EXPECT_LT(run.arcStartAfter[a], run.arcEndAfter[a]);
    if (a + 1 < 3) {
      EXPECT_LT(run.arcEndAfter[a], run.arcStartAfter[a + 1]);
    }
  }
  size_t joint = 0;
  for (size_t i = 0; i < run.moves.size(); ++i) {
    const test::TpMove& m = run.moves[i];
    bool arc = false;
    int arcIndex = -1;
    for (size_t a = 0; a < 3; ++a)
      if (i >= run.arcStartAfter[a] && i < run.arcEndAfter[a]) {
        arc = true;  // the move after i runs with the arc on
        arcIndex = static_cast<int>(a);
      }
    // The AO point logic of line i acts as P[i] is reached, i.e. on the move after it.
    if (m.options.find("AO[") != std::string::npos) {
      EXPECT_TRUE(arc) << "AO with the arc off at move " << i;
    }
    if (i > 0 && m.type == 'J') ++joint;
    if (arc && i > run.arcStartAfter[static_cast<size_t>(arcIndex)]) {
      EXPECT_LT(distanceToPath(test::tpPose(m.pos).translation(), plan, arcIndex), kOnPath) << i;
    }
  }
  EXPECT_EQ(joint, 2u);  // one joint move per change of sub-path
}

// On the KUKA cell every sub-path keeps one configuration (S) and the travel reaches the next
// sub-path by a PTP, where S may change.
TEST(MultiPathExport, OneConfigurationInsideEachSubPathOnARealCell)
{
  const RobotCell cell(readCellFile(test::sourceDir() / "resources/cells/kuka_kr16_2_table.cell"));
  const Trajectory plan = threePathPlan();
  test::TempDir dir;
  const ExportOutcome out = runJob("export.krl", plan, &cell, dir.path());
  EXPECT_EQ(out.unreachableTargets, 0u);
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  bool arc = false;
  std::vector<std::set<int>> status;
  for (const test::KrlMove& m : run.moves) {
    for (const auto& t : m.triggers)
      if (t.find("$OUT[1]=TRUE") != std::string::npos) {
        arc = true;
        status.emplace_back();
      }
    if (arc) {
      ASSERT_TRUE(m.pose.s.has_value());
      status.back().insert(*m.pose.s);
    }
    for (const auto& t : m.triggers)
      if (t.find("$OUT[1]=FALSE") != std::string::npos) arc = false;
  }
  ASSERT_EQ(status.size(), 3u);
  for (const auto& s : status) EXPECT_EQ(s.size(), 1u);
}

}  // namespace
}  // namespace spira
