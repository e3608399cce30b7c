#include <gtest/gtest.h>

#include "builtin_plugins.h"
#include "spira/base/progress.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/plan_advice.h"
#include "spira/planning/planner.h"

namespace spira::test {
namespace {

// A 20 mm tall open tube at h = 2 mm, +/- 10 %: the start-up and the termination take 6
// revolutions each (thesis Table 3.1), about 12 h = 24 mm with one layer of h_min, longer than the
// wall. The ramps scale with h, and what is left must be whole layers inside the window, so the
// advice is the largest h on the 0.05 mm grid that plans: the test plans it, and every larger h
// of the grid below 2 mm, on its own.
TEST(ShortPartAdvice, ATubeTooShortForItsRampsGetsTheDepositThatFitsCheckedByPlanning)
{
  const TriangleMesh tube = makeOpenCylinder(30.0, 20.0, 120, 20);
  const MeshReport report = validateMesh(tube);
  PlanRequest request(tube, report);
  NullProgress progress;
  try {
    planPart(builtinRegistry(), request, progress);
    FAIL() << "a 20 mm wall held 24 mm of ramps";
  } catch (const TooShortError& e) {
    EXPECT_NEAR(e.length(), 20.0, 1e-6);
    EXPECT_GT(e.needed(), 20.0);
    const PlanAdvice advice = adviseSmallerDeposit(builtinRegistry(), request, e, progress);
    ASSERT_TRUE(advice.found) << advice.text();
    ASSERT_EQ(advice.flags.rfind("--h ", 0), 0u) << advice.flags;
    const double h = std::stod(advice.flags.substr(4));
    EXPECT_GE(h, kThinnestAdvisedDeposit);
    for (double larger = h + 0.05; larger < 2.0 - 1e-9; larger += 0.05) {
      PlanRequest r = request;
      r.params["spiral"].set("h", larger);
      try {
        EXPECT_FALSE(planPart(builtinRegistry(), r, progress).feasible()) << "h = " << larger << " plans";
      } catch (const InputError&) {
      }
    }
    PlanRequest smaller = request;
    smaller.params["spiral"].set("h", h);
    const PlanOutput plan = planPart(builtinRegistry(), smaller, progress);
    EXPECT_TRUE(plan.feasible()) << plan.deposits.summary();
    EXPECT_NEAR(plan.spiral.trajectory.points.back().position.z(), 20.0, 1e-6);
  }
}

}  // namespace
}  // namespace spira::test
