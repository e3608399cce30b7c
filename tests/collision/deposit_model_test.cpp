#include <gtest/gtest.h>

#include "collision/plan_builders.h"
#include "spira/base/error.h"
#include "spira/collision/deposit_model.h"

namespace spira {
namespace {

// A straight bead along +X, one point per millimetre.
Trajectory straightLine(int count)
{
  Trajectory plan;
  for (int i = 0; i < count; ++i) plan.points.push_back(test::wallPoint(i, 0, 1, true));
  return plan;
}

TEST(DepositModel, TheSlidingWindowHidesTheLastMillimetresOfArcLength)
{
  const Trajectory plan = straightLine(100);
  const DepositModel model(plan, DepositParams(), 23.0);
  EXPECT_EQ(model.capsules().size(), 99u);
  for (size_t i = 0; i < plan.size(); ++i) {
    // Segment k ends at x = k + 1; it is visible when k + 1 <= i - 23.
    EXPECT_EQ(model.visibleEnd(i), i > 23 ? i - 23 : 0u) << "point " << i;
    EXPECT_DOUBLE_EQ(model.arcLength(i), double(i));
  }
  const DepositModel noWindow(plan, DepositParams(), 0.0);
  for (size_t i = 0; i < plan.size(); ++i) EXPECT_EQ(noWindow.visibleEnd(i), i);
}

TEST(DepositModel, BeadTopsPassThroughThePathAndArcOffSegmentsLayNothing)
{
  Trajectory plan = straightLine(10);
  plan.points[4].arcOn = false;  // the segment from point 4 to 5 is a travel move
  DepositParams params;
  params.beadWidth = 5.0;
  const DepositModel model(plan, params, 0.0);
  ASSERT_EQ(model.capsules().size(), 8u);
  for (size_t c = 0; c < model.capsules().size(); ++c) {
    const Capsule& cap = model.capsules().capsule(c);
    const uint32_t k = model.capsules().key(c);
    EXPECT_NE(k, 4u);
    EXPECT_DOUBLE_EQ(cap.radius, 2.5);
    // Axis sunk by the radius along -b (b = +Z), so the top of the bead is at the path point.
    EXPECT_NEAR((cap.a - Vec3(k, 0, 1 - 2.5)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((cap.b - Vec3(k + 1, 0, 1 - 2.5)).norm(), 0.0, 1e-12);
  }
  params.topAtPath = false;
  const DepositModel centred(plan, params, 0.0);
  EXPECT_NEAR((centred.capsules().capsule(0).a - Vec3(0, 0, 1)).norm(), 0.0, 1e-12);
}

TEST(DepositModel, RejectsABadBeadWidthOrWindow)
{
  const Trajectory plan = straightLine(5);
  DepositParams params;
  params.beadWidth = 0.0;
  EXPECT_THROW(DepositModel(plan, params, 1.0), InputError);
  EXPECT_THROW(DepositModel(plan, DepositParams(), -1.0), InputError);
}

}  // namespace
}  // namespace spira
