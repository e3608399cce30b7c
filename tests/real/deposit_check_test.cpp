// The test-side deposit check on tiny trajectories made by hand, one rule at a time.
#include <gtest/gtest.h>

#include <cmath>

#include "real/deposit_check.h"

namespace spira::test::real {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 30.0;
constexpr int kPerRing = 120;  // 1.57 mm steps on a 30 mm ring
constexpr double kH = 2.0;

// Rings of radius 30 mm stacked 2 mm apart, the first 2 mm above the substrate, each joined to
// the next by a short step up at the seam: one sub-path, the arc on throughout.
std::vector<PathPoint> stackedRings(int rings)
{
  std::vector<PathPoint> pts;
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < kPerRing; ++j) {
      const double a = 2 * kPi * j / kPerRing;
      PathPoint p;
      p.p = V3(kRadius * std::cos(a), kRadius * std::sin(a), kH * (k + 1));
      pts.push_back(p);
    }
  return pts;
}

size_t indexOf(int ring, int j)
{
  return static_cast<size_t>(ring * kPerRing + j);
}

// A cylinder of radius 30 mm from z0 to z1, 60 facets round, 2 mm tall bands.
std::vector<Triangle> cylinder(double z0, double z1)
{
  std::vector<Triangle> tris;
  const int around = 60;
  const int bands = static_cast<int>(std::round((z1 - z0) / 2.0));
  auto at = [&](int i, int k) {
    const double a = 2 * kPi * i / around;
    return V3(kRadius * std::cos(a), kRadius * std::sin(a), z0 + (z1 - z0) * k / bands);
  };
  for (int k = 0; k < bands; ++k)
    for (int i = 0; i < around; ++i) {
      tris.push_back({at(i, k), at(i + 1, k), at(i + 1, k + 1)});
      tris.push_back({at(i, k), at(i + 1, k + 1), at(i, k + 1)});
    }
  return tris;
}

TEST(DepositCheck, StackedRingsPass)
{
  const CheckResult r = checkDeposit(stackedRings(10), CheckSettings{});
  EXPECT_EQ(r.checked, 10u * kPerRing);
  EXPECT_EQ(r.flagged(), 0u) << r.summary();
  EXPECT_NEAR(r.heightMin, kH, 1e-9);
  EXPECT_NEAR(r.heightMax, kH, 1e-9);
  EXPECT_TRUE(r.feasible());
}

TEST(DepositCheck, RingLiftedThirtyMillimetresIsUnsupported)
{
  auto pts = stackedRings(10);
  for (int j = 0; j < kPerRing; ++j) pts[indexOf(5, j)].p.z += 30.0;
  const CheckResult r = checkDeposit(pts, CheckSettings{});
  // Nothing lies within reach under the lifted ring: only the substrate, 42 mm down.
  EXPECT_EQ(r.unsupported, static_cast<size_t>(kPerRing)) << r.summary();
  // The ring above it now stands 4 mm over ring 4: thicker than the process lays.
  EXPECT_EQ(r.thick, static_cast<size_t>(kPerRing)) << r.summary();
  // The 30 mm climbs into and out of the lifted ring with the arc on.
  EXPECT_EQ(r.jump, 2u) << r.summary();
  EXPECT_FALSE(r.feasible());
  ASSERT_FALSE(r.firstOffenders.empty());
  EXPECT_EQ(r.firstOffenders.front().index, indexOf(5, 0));
}

TEST(DepositCheck, PointUnderThePreviousRingIsBelowDeposit)
{
  auto pts = stackedRings(10);
  pts[indexOf(6, 40)].p.z -= 3.0;  // 1 mm under ring 5
  const CheckResult r = checkDeposit(pts, CheckSettings{});
  EXPECT_GE(r.below, 1u) << r.summary();
  bool found = false;
  for (const Offender& o : r.firstOffenders)
    if (o.index == indexOf(6, 40) && o.flag == Flag::BelowDeposit) {
      found = true;
      EXPECT_NEAR(o.height, -1.0, 1e-9);
    }
  EXPECT_TRUE(found) << r.summary();
  EXPECT_FALSE(r.feasible());
}

TEST(DepositCheck, ArcOnAcrossAGapIsAJump)
{
  auto pts = stackedRings(4);
  // Twelve points (19 mm of ring 3) dropped with the arc left on across the gap.
  pts.erase(pts.begin() + static_cast<long>(indexOf(3, 50)), pts.begin() + static_cast<long>(indexOf(3, 62)));
  const CheckResult r = checkDeposit(pts, CheckSettings{});
  EXPECT_EQ(r.jump, 1u) << r.summary();
  EXPECT_EQ(r.unsupported + r.thin + r.thick + r.below, 0u) << r.summary();
  EXPECT_FALSE(r.feasible());

  // The same gap with the arc off across it is a travel move, not a jump.
  auto travel = pts;
  travel[indexOf(3, 49)].arc = false;
  EXPECT_EQ(checkDeposit(travel, CheckSettings{}).jump, 0u);
}

// docs/deposit-check.md: each sub-path has its own arc start and stop, the program travels between them
// with the arc off, so the step into a new sub-path is no jump; its beads still rest on the earlier ones.
TEST(DepositCheck, ChangingSubPathWithTheArcOnStartsANewArcNotAJump)
{
  auto pts = stackedRings(3);
  for (size_t i = indexOf(2, 0); i < pts.size(); ++i) pts[i].path = 1;
  const CheckResult r = checkDeposit(pts, CheckSettings{});
  EXPECT_EQ(r.jump, 0u);
  EXPECT_TRUE(r.feasible()) << r.summary();
  // Within a sub-path the same step is a jump.
  auto far = stackedRings(3);
  for (size_t i = indexOf(2, 0); i < far.size(); ++i) far[i].p.z += 10.0;
  EXPECT_GE(checkDeposit(far, CheckSettings{}).jump, 1u);
}

TEST(DepositCheck, MissingBandOfCoverage)
{
  const auto wall = cylinder(0.0, 20.0);
  const CheckResult full = checkDeposit(stackedRings(10), CheckSettings{}, wall);
  EXPECT_TRUE(full.coverageChecked);
  EXPECT_NEAR(full.surfaceArea, 2 * kPi * kRadius * 20.0, 0.01 * full.surfaceArea);
  EXPECT_LE(full.uncoveredFraction(), 0.005) << full.summary();
  EXPECT_TRUE(full.feasible()) << full.summary();

  // Rings 3 to 6 (z = 8 .. 14 mm) missing: the wall from about 8.6 to 13.4 mm is farther than
  // the bead's reach (2.6 mm) from any segment.
  auto pts = stackedRings(10);
  pts.erase(pts.begin() + static_cast<long>(indexOf(3, 0)), pts.begin() + static_cast<long>(indexOf(7, 0)));
  const CheckResult gap = checkDeposit(pts, CheckSettings{}, wall);
  EXPECT_GT(gap.uncoveredFraction(), 0.1) << gap.summary();
  EXPECT_GT(gap.maxDistance, 2.6) << gap.summary();
  EXPECT_FALSE(gap.feasible());
}

// Ring 1's first point a tenth of a step behind ring 0's first (the arc start): it rests on ring
// 0 (2 mm), not on the substrate (4 mm), and ring 0's last point, a step before the arc start,
// still stands on the substrate.
TEST(DepositCheck, SecondRingStartingAHairBehindTheArcStartRestsOnIt)
{
  auto pts = stackedRings(3);
  const double back = 0.1 * 2 * kPi / kPerRing;
  pts[indexOf(1, 0)].p = V3(kRadius * std::cos(-back), kRadius * std::sin(-back), 2 * kH);
  const CheckResult r = checkDeposit(pts, CheckSettings{});
  EXPECT_EQ(r.flagged(), 0u) << r.summary();
  EXPECT_NEAR(r.heightMax, kH, 1e-9);
}

// A solid's base face, 4.8 mm wide under the first ring (2 mm up): its edges lie 2.4 mm sideways
// and 2 mm below the ring, out of the 2.61 mm ball, but inside the bead's 5.2 mm footprint on the
// substrate. Twice as wide, its edges are uncovered.
TEST(DepositCheck, BaseFaceUnderTheFirstRingIsCoveredByTheBeadsFootprint)
{
  const int around = 120;
  auto annulus = [&](double r0, double r1) {
    std::vector<Triangle> tris;
    auto at = [&](double r, int i) {
      const double a = 2 * kPi * i / around;
      return V3(r * std::cos(a), r * std::sin(a), 0.0);
    };
    for (int i = 0; i < around; ++i) {
      tris.push_back({at(r0, i), at(r0, i + 1), at(r1, i + 1)});
      tris.push_back({at(r0, i), at(r1, i + 1), at(r1, i)});
    }
    return tris;
  };
  const CheckResult narrow =
      checkDeposit(stackedRings(2), CheckSettings{}, annulus(kRadius - 2.4, kRadius + 2.4));
  EXPECT_EQ(narrow.uncoveredArea, 0.0) << narrow.summary();
  const CheckResult wide =
      checkDeposit(stackedRings(2), CheckSettings{}, annulus(kRadius - 4.8, kRadius + 4.8));
  EXPECT_GT(wide.uncoveredFraction(), 0.3) << wide.summary();
}

// A run's last point lays the end of its bead (a closed part's closure point inside its last ring):
// with material within a bead width it is not judged; farther away it is, like any point.
TEST(DepositCheck, ARunsLastPointEndsItsBeadOnMaterialWithinABeadWidth)
{
  for (const double inside : {3.0, 10.0}) {
    std::vector<PathPoint> pts = stackedRings(3);
    PathPoint end;
    end.p = V3(kRadius - inside, 0.0, 3 * kH);
    pts.push_back(end);
    const CheckResult r = checkDeposit(pts, CheckSettings{});
    EXPECT_EQ(r.unsupported, inside < CheckSettings{}.beadWidth ? 0u : 1u) << inside << ": " << r.summary();
    EXPECT_EQ(r.flagged(), r.unsupported) << r.summary();
  }
}

TEST(DepositCheck, SubstrateBelowTheFirstRing)
{
  auto pts = stackedRings(2);
  CheckSettings s;
  s.substrateZ = -1.0;  // the first ring now stands 3 mm over the plate
  const CheckResult r = checkDeposit(pts, s);
  EXPECT_EQ(r.thick, static_cast<size_t>(kPerRing)) << r.summary();
}

}  // namespace
}  // namespace spira::test::real
