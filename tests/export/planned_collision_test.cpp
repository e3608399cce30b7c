// Collisions the plan left unresolved reach the program: the targets standing for colliding
// planned points are refused unless forced, and forced they carry the warning comment.
#include <gtest/gtest.h>

#include <algorithm>

#include "builtin_plugins.h"
#include "export_test_data.h"
#include "krl_reader.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/pipeline/export_job.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/robotcell/cell_file.h"
#include "support/test_support.h"

namespace spira {
namespace {

TEST(PlannedCollisions, AreRefusedUnlessForcedAndThenCommentedWhereTheyAre)
{
  const RobotCell cell(readCellFile(test::sourceDir() / "resources/cells/kuka_kr16_2_table.cell"));
  const Trajectory plan = test::cylinderPlan(2, 36, 30.0, 2.0);
  ExportJob job;
  job.exporterId = "export.krl";
  job.cell = &cell;
  job.header = test::testHeader();
  job.plannedCollision.assign(plan.size(), false);
  for (size_t i = 40; i <= 42; ++i) job.plannedCollision[i] = true;
  NullProgress progress;
  test::TempDir refused;
  try {
    exportTrajectory(builtinRegistry(), plan, job, refused.path(), progress);
    ADD_FAILURE() << "a plan with collisions was exported";
  } catch (const InfeasibleError& e) {
    EXPECT_NE(std::string(e.what()).find("in collision"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(test::filesIn(refused.path()).empty());

  job.exporterParams.set("force", true);
  test::TempDir forced;
  exportTrajectory(builtinRegistry(), plan, job, forced.path(), progress);
  const test::KrlRun run = test::runKrl(forced.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  // Every flagged move's target lies on the planned stretch from point 39 to 43 (the colliding
  // points and the intervals touching them). Targets are in the robot base frame.
  const Transform partBase = cell.setup().basePart.inverse();
  const auto nearStretch = [&plan](const Vec3& q) {
    double best = 1e9;
    for (size_t i = 40; i <= 43; ++i) {
      const Vec3 a = plan.points[i - 1].position, d = plan.points[i].position - a;
      const double u = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + u * d - q).norm());
    }
    return best;
  };
  size_t flagged = 0;
  for (const test::KrlMove& m : run.moves) {
    bool warned = false;
    for (const auto& c : m.comments) warned = warned || c.find("in collision") != std::string::npos;
    if (!warned) continue;
    ++flagged;
    EXPECT_LT(nearStretch(partBase * m.pose.xyz), 0.2) << m.target;
  }
  EXPECT_GE(flagged, 3u);
}

}  // namespace
}  // namespace spira
