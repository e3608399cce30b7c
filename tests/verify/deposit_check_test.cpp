#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "spira/base/units.h"
#include "spira/verify/deposit_check.h"

namespace spira {
namespace {

constexpr double kRadius = 30.0;
constexpr int kPointsPerRing = 360;

// A ring-by-ring spiral on a vertical cylinder as a spiral builder would lay it: the first ring
// climbs from h_min to h_max above the substrate, every later ring lies h = 2 mm above the last.
// `lift(ring, k)` adds to the height of point k of a ring.
Trajectory cylinderSpiral(int rings, const std::function<double(int, int)>& lift = {})
{
  Trajectory t;
  for (int r = 0; r < rings; ++r)
    for (int k = 0; k < kPointsPerRing; ++k) {
      const double a = 2.0 * kPi * k / kPointsPerRing;
      TrajectoryPoint p;
      const double z = 1.5 + double(k) / kPointsPerRing + 2.0 * r;
      p.position = Vec3(kRadius * std::cos(a), kRadius * std::sin(a), z + (lift ? lift(r, k) : 0.0));
      p.normal = Vec3(std::cos(a), std::sin(a), 0.0);
      p.tangent = Vec3(-std::sin(a), std::cos(a), 0.0);
      p.build = Vec3::UnitZ();
      p.revolution = r;
      p.generatrix = k;
      p.height = r == 0 ? z : 2.0;
      t.points.push_back(p);
    }
  return t;
}

DepositCheckSettings window()
{
  DepositCheckSettings s;
  s.hMin = 1.5;
  s.hMax = 2.5;
  s.tolerance = 0.01;
  s.beadWidth = 4.0;
  return s;
}

// The cylinder's wall from z = 0 to `height`, 180 facets around, 1 mm rows.
TriangleMesh cylinderWall(double height)
{
  TriangleMesh m;
  const int around = 180, rows = static_cast<int>(std::ceil(height));
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2.0 * kPi * i / around;
      m.vertices.emplace_back(kRadius * std::cos(a), kRadius * std::sin(a), height * j / rows);
    }
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      const int a = j * around + i, b = j * around + (i + 1) % around;
      m.faces.push_back({a, b, b + around});
      m.faces.push_back({a, b + around, a + around});
    }
  return m;
}

DepositCheckReport check(const Trajectory& t, const TriangleMesh* surface = nullptr)
{
  NullProgress progress;
  return checkDeposits(t, surface, window(), progress);
}

TEST(DepositCheck, StackedRingsAreSupportedAtTheirTrueHeights)
{
  const DepositCheckReport r = check(cylinderSpiral(20));
  EXPECT_TRUE(r.feasible) << r.summary();
  EXPECT_EQ(r.pointsChecked, 20u * kPointsPerRing);
  EXPECT_TRUE(r.flags.empty());
  // The first ring stands on the substrate (1.5 .. 2.5 mm), every other ring 2 mm above the last.
  EXPECT_NEAR(r.heightMin, 1.5, 1e-9);
  EXPECT_NEAR(r.heightMax, 2.5 - 1.0 / kPointsPerRing, 1e-9);
  EXPECT_LT(r.plannedDifferenceMax, 1e-6);
}

TEST(DepositCheck, RingLiftedIntoMidAirIsUnsupportedAndItsSeamAJump)
{
  const DepositCheckReport r =
      check(cylinderSpiral(12, [](int ring, int) { return ring >= 6 ? 30.0 : 0.0; }));
  EXPECT_FALSE(r.feasible);
  EXPECT_EQ(r.count(DepositDefect::Unsupported), size_t(kPointsPerRing));
  EXPECT_EQ(r.count(DepositDefect::Jump), 1u);
  const DepositFlag& first = r.flags.front();
  EXPECT_EQ(first.point, 6u * kPointsPerRing);
  // The seam segment rises 31 mm more than a seam does; ring 6 stands 32 mm above ring 5.
  EXPECT_EQ(first.kind, DepositDefect::Jump);
  const double rise = 31.0 + 1.0 / kPointsPerRing, chord = 2.0 * kRadius * std::sin(kPi / kPointsPerRing);
  EXPECT_NEAR(first.height, std::hypot(rise, chord), 1e-9);
  const DepositFlag& lifted = r.flags[1];
  EXPECT_EQ(lifted.kind, DepositDefect::Unsupported);
  EXPECT_NEAR(lifted.height, 32.0, 1e-6);
  EXPECT_NE(r.summary().find("in mid-air"), std::string::npos) << r.summary();
  // The measured range covers the rejected points too.
  EXPECT_NEAR(r.heightMax, 32.0, 1e-6);
}

// hMax = 2.5 mm: material is looked for at most 25 mm below a point, the substrate plane excepted
// (always measured). With the substrate 1000 mm down, the first ring is unsupported at its true
// distance from it, and a ring 60 mm above the last one, out of reach of the rings below, is
// measured against the substrate too.
TEST(DepositCheck, RingFarAboveEverythingHasNothingWithinTheSearchDepth)
{
  DepositCheckSettings s = window();
  s.substrateZ = -1000.0;
  NullProgress none;
  const DepositCheckReport r = checkDeposits(
      cylinderSpiral(8, [](int ring, int) { return ring >= 4 ? 60.0 : 0.0; }), nullptr, s, none);
  EXPECT_NEAR(r.searchDepth, 25.0, 1e-12);
  ASSERT_EQ(r.count(DepositDefect::Unsupported), size_t(2 * kPointsPerRing));
  std::vector<const DepositFlag*> unsupported;
  for (const DepositFlag& f : r.flags)
    if (f.kind == DepositDefect::Unsupported) unsupported.push_back(&f);
  EXPECT_EQ(unsupported.front()->point, 0u);
  EXPECT_NEAR(unsupported.front()->height, 1001.5, 1e-9);
  const DepositFlag& lifted = *unsupported[kPointsPerRing];
  EXPECT_EQ(lifted.point, 4u * kPointsPerRing);
  EXPECT_NEAR(lifted.height, 1069.5, 1e-9);
  EXPECT_NE(r.summary().find("point 0 at (30.0, 0.0, 1.5) mm is 1001.50 mm above the material below it"),
            std::string::npos)
      << r.summary();
}

// The second ring's first point laid a twentieth of a step behind the arc start, as a seam's
// rounding leaves it: it rests on the first ring's start (2 mm), not on the substrate (3.5 mm),
// and the first ring's last point, a step before the arc start, still stands on the substrate.
TEST(DepositCheck, SecondRingStartingAHairBehindTheArcStartRestsOnIt)
{
  Trajectory t = cylinderSpiral(3);
  TrajectoryPoint& p = t.points[kPointsPerRing];
  p.position -= 0.05 * (2.0 * kPi * kRadius / kPointsPerRing) * p.tangent;
  const DepositCheckReport r = check(t);
  EXPECT_TRUE(r.flags.empty()) << r.summary();
  EXPECT_NEAR(r.heightMax, 2.5, 0.005);  // the first ring's last point, 1.5 + 359 / 360
  EXPECT_NEAR(r.heightMin, 1.5, 1e-6);
}

TEST(DepositCheck, PointPushedUnderThePreviousRingLiesBelowTheDeposit)
{
  const int ring = 5, at = 180;
  const DepositCheckReport r =
      check(cylinderSpiral(10, [&](int rr, int k) { return rr == ring && k == at ? -3.0 : 0.0; }));
  EXPECT_FALSE(r.feasible);
  ASSERT_EQ(r.count(DepositDefect::BelowDeposit), 1u);
  const auto below = std::find_if(r.flags.begin(), r.flags.end(),
                                  [](const DepositFlag& f) { return f.kind == DepositDefect::BelowDeposit; });
  EXPECT_EQ(below->point, size_t(ring * kPointsPerRing + at));
  EXPECT_NEAR(below->height, -1.0, 1e-6);
  // The next ring lies 5 mm above the dent, beyond h_max.
  EXPECT_EQ(r.count(DepositDefect::Thick), 1u);
}

TEST(DepositCheck, ArcOnJumpIsFlaggedAndNotTakenForMaterial)
{
  Trajectory t = cylinderSpiral(8);
  // 30 points (15.7 mm of ring 3) left out: the arc bridges them in one straight move.
  t.points.erase(t.points.begin() + 3 * kPointsPerRing + 100, t.points.begin() + 3 * kPointsPerRing + 130);
  const DepositCheckReport r = check(t);
  EXPECT_FALSE(r.feasible);
  ASSERT_EQ(r.count(DepositDefect::Jump), 1u);
  EXPECT_EQ(r.flags.front().point, size_t(3 * kPointsPerRing + 100));
  EXPECT_NEAR(r.flags.front().height, 2.0 * kRadius * std::sin(kPi * 31 / kPointsPerRing), 0.05);
  // Ring 4 over the bridged stretch finds ring 2, 4 mm down.
  EXPECT_GT(r.count(DepositDefect::Thick), 20u);
  EXPECT_EQ(r.count(DepositDefect::Unsupported), 0u);
}

TEST(DepositCheck, ArcOffTravelIsNeitherMaterialNorAJump)
{
  Trajectory t = cylinderSpiral(4);
  for (int k = 0; k < kPointsPerRing; ++k) t.points[size_t(3 * kPointsPerRing + k)].arcOn = false;
  const DepositCheckReport r = check(t);
  EXPECT_TRUE(r.feasible) << r.summary();
  EXPECT_EQ(r.pointsChecked, 3u * kPointsPerRing);
}

TEST(DepositCheck, UncoveredBandAboveTheLastRingIsMeasured)
{
  const int rings = 10;
  const Trajectory t = cylinderSpiral(rings);
  const double top = 2.5 + 2.0 * (rings - 1);  // highest point of the last ring
  const TriangleMesh exact = cylinderWall(std::ceil(top));
  const DepositCheckReport covered = check(t, &exact);
  EXPECT_TRUE(covered.feasible) << covered.summary();
  EXPECT_EQ(covered.uncoveredArea, 0.0);
  EXPECT_LT(covered.largestGap, 2.51);

  const double extra = 12.0;
  const TriangleMesh taller = cylinderWall(std::ceil(top) + extra);
  const DepositCheckReport r = check(t, &taller);
  EXPECT_FALSE(r.feasible);
  EXPECT_TRUE(r.flags.empty());
  // The band beyond the cover radius (2.51 mm) over the last ring's rising top, about 2 pi R x 10 mm.
  const double band = 2.0 * kPi * kRadius * (std::ceil(top) + extra - (top - 0.5) - 2.51);
  EXPECT_NEAR(r.uncoveredArea, band, 0.05 * band);
  EXPECT_NEAR(r.largestGap, std::ceil(top) + extra - (top - 1.0), 0.5);
  EXPECT_NE(r.summary().find("not covered"), std::string::npos) << r.summary();
}

// A flat ring on the substrate plane from radius r0 to r1, 180 facets around.
TriangleMesh annulus(double r0, double r1)
{
  TriangleMesh m;
  const int around = 180;
  for (double r : {r0, r1})
    for (int i = 0; i < around; ++i) {
      const double a = 2.0 * kPi * i / around;
      m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
    }
  for (int i = 0; i < around; ++i) {
    const int a = i, b = (i + 1) % around;
    m.faces.push_back({a, b, b + around});
    m.faces.push_back({a, b + around, a + around});
  }
  return m;
}

// The base face of a thin-walled solid, 3.6 mm wide under the first ring (radius 30, 1.5 to
// 2.5 mm up): its inner and outer edges lie 1.8 mm sideways and up to 2.5 mm below the ring, out
// of the 2.51 mm ball, but inside the bead's 4 mm footprint on the substrate. Wider than the
// footprint, the face's edges are uncovered.
TEST(DepositCheck, BaseFaceUnderTheFirstRingIsCoveredByTheBeadsFootprint)
{
  const Trajectory t = cylinderSpiral(3);
  const TriangleMesh face = annulus(kRadius - 1.8, kRadius + 1.8);
  const DepositCheckReport r = check(t, &face);
  EXPECT_EQ(r.uncoveredArea, 0.0) << r.summary();
  const TriangleMesh wide = annulus(kRadius - 3.0, kRadius + 3.0);
  const DepositCheckReport w = check(t, &wide);
  // Beyond 2 mm sideways: 2 x 2 pi R x 1 mm, less the ball's reach where the ring is 1.5 mm up.
  EXPECT_GT(w.uncoveredArea, 0.5 * 2.0 * 2.0 * kPi * kRadius) << w.summary();
  EXPECT_LT(w.uncoveredArea, 2.0 * 2.0 * kPi * kRadius * 1.0) << w.summary();
}

// Each sub-path has its own arc start and stop: a branch starting where its sub-path starts is no
// jump, and it stands on what the earlier sub-paths laid.
TEST(DepositCheck, SubPathsAreSeparateArcsOnEarlierMaterial)
{
  Trajectory t = cylinderSpiral(6);
  for (size_t i = 3 * kPointsPerRing; i < t.size(); ++i) t.points[i].path = 1;
  const DepositCheckReport r = check(t);
  EXPECT_TRUE(r.feasible) << r.summary();
  // Lifted by 10 mm, the second sub-path starts in mid-air, still without a jump.
  for (size_t i = 3 * kPointsPerRing; i < t.size(); ++i) t.points[i].position.z() += 10.0;
  const DepositCheckReport lifted = check(t);
  EXPECT_EQ(lifted.count(DepositDefect::Jump), 0u);
  EXPECT_EQ(lifted.count(DepositDefect::Unsupported), size_t(kPointsPerRing));
}

}  // namespace
}  // namespace spira

namespace spira {
namespace {

// A flat plate as a mesh, `tilt` (rad) about y, through (0, 0, z0): a square of 2 x 80 triangles.
TriangleMesh plateMesh(double z0, double tilt = 0.0)
{
  TriangleMesh m;
  const double half = 80.0;
  for (int i = 0; i < 4; ++i) {
    const double x = (i & 1) ? half : -half, y = (i & 2) ? half : -half;
    m.vertices.emplace_back(x * std::cos(tilt), y, z0 + x * std::sin(tilt));
  }
  m.faces.push_back({0, 1, 3});
  m.faces.push_back({0, 3, 2});
  return m;
}

DepositCheckReport checkOn(const Trajectory& t, const TriangleMesh& substrate)
{
  DepositCheckSettings s = window();
  s.substrate = std::make_shared<const SubstrateSurface>(SubstrateSurface::mesh(substrate));
  s.substrateZ = -1000.0;  // the plane is not used when the substrate is a mesh
  NullProgress progress;
  return checkDeposits(t, nullptr, s, progress);
}

// A substrate mesh stands for the plate: the first ring measured down to it, as to the plane.
TEST(DepositCheckOnAMesh, AFlatMeshGivesThePlatesHeights)
{
  const DepositCheckReport r = checkOn(cylinderSpiral(5), plateMesh(0.0));
  EXPECT_TRUE(r.feasible) << r.summary();
  EXPECT_NEAR(r.heightMin, 1.5, 1e-9);
  EXPECT_NEAR(r.heightMax, 2.5 - 1.0 / kPointsPerRing, 1e-9);
}

// Tilted by 1 deg about y through z = 0, the plate lies 30 sin(1 deg) = 0.52 mm higher under the ring's
// +x side and as much lower under its -x side: the first ring's heights spread by that much.
TEST(DepositCheckOnAMesh, ATiltedMeshMeasuresTheFirstRingDownToItself)
{
  const double tilt = degToRad(1.0);
  const DepositCheckReport r = checkOn(cylinderSpiral(5), plateMesh(0.0, tilt));
  EXPECT_NEAR(r.heightMin, 1.5 - kRadius * std::tan(tilt), 0.01);
  // Raised by 1 mm, the plate is under the first ring's start: below the deposit there.
  const DepositCheckReport under = checkOn(cylinderSpiral(5), plateMesh(1.6));
  EXPECT_FALSE(under.feasible);
  EXPECT_GT(under.counts[int(DepositDefect::BelowDeposit)] + under.counts[int(DepositDefect::Thin)], 0u);
  // Far below, nothing supports the first ring.
  const DepositCheckReport far = checkOn(cylinderSpiral(5), plateMesh(-30.0));
  EXPECT_GT(far.counts[int(DepositDefect::Unsupported)], 0u);
}

}  // namespace
}  // namespace spira
