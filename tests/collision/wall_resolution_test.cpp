#include <gtest/gtest.h>

#include <cmath>

#include "collision/plan_builders.h"
#include "spira/base/units.h"
#include "spira/collision/collision_resolver.h"

namespace spira {
namespace {

using V2 = Eigen::Vector2d;

constexpr int kLayers = 20;  // wall A: 20 layers, 1 mm each, top at z = 20
constexpr double kLength = 120.0;
constexpr double kGap = 10.0;  // wall B runs 10 mm beside wall A, on its first layer

// Wall A laid back and forth along X at y = 0, then the first layer of wall B at y = kGap, whose
// torch (nozzle tip 15 mm up, cone widening to 20 mm) reaches into the top of wall A.
Trajectory plantedWalls(std::vector<size_t>& wallB)
{
  Trajectory plan;
  for (int layer = 0; layer < kLayers; ++layer) {
    const bool forward = layer % 2 == 0;
    for (int k = 0; k <= int(kLength); ++k) {
      const double x = forward ? k : kLength - k;
      plan.points.push_back(test::wallPoint(x, 0.0, 1.0 + layer, forward));
    }
  }
  plan.points.back().arcOn = false;  // travel to wall B
  for (int k = 0; k <= int(kLength); ++k) {
    wallB.push_back(plan.size());
    plan.points.push_back(test::wallPoint(k, kGap, 1.0, true));
  }
  return plan;
}

// Independent truth for the middle of wall B: wall A is long and straight along X and the torch
// tilts about X, so the torch-to-bead distance is the 2-D distance between the torch's section in
// the YZ plane (a convex polygon) and the bead centres (y = 0, z = top - r), minus the bead radius.
double sectionClearance(double tilt, const TorchParams& p, double beadRadius)
{
  const V2 tcp(kGap, 1.0);
  // b' = cos(a) b + sin(a) n with b = +Z and n = -Y: a negative tilt leans the axis towards +Y,
  // away from wall A. (y, z) components:
  const V2 axis(-std::sin(tilt), std::cos(tilt)), side(std::cos(tilt), std::sin(tilt));
  const double s0 = p.standoff, s1 = s0 + p.coneLength, s2 = s1 + p.bodyLength;
  const V2 poly[6] = {tcp + s0 * axis - p.nozzleRadius * side, tcp + s0 * axis + p.nozzleRadius * side,
                      tcp + s1 * axis + p.bodyRadius * side,   tcp + s2 * axis + p.bodyRadius * side,
                      tcp + s2 * axis - p.bodyRadius * side,   tcp + s1 * axis - p.bodyRadius * side};
  double best = std::numeric_limits<double>::infinity();
  for (int layer = 0; layer < kLayers; ++layer) {
    const V2 c(0.0, 1.0 + layer - beadRadius);
    for (int k = 0; k < 6; ++k) {
      const V2 a = poly[k], b = poly[(k + 1) % 6];
      const double t = std::clamp((c - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + t * (b - a) - c).norm() - beadRadius);
    }
  }
  return best;
}

TEST(WallResolution, APlantedBeadIsDetectedAndClearedByTiltingAboutTheTravelDirection)
{
  std::vector<size_t> wallB;
  const Trajectory plan = plantedWalls(wallB);
  const TorchParams torch;
  const DepositParams deposit;  // 4 mm beads, default window
  CollisionScene scene;
  scene.setSubstratePlane(Vec3::Zero(), Vec3::UnitZ());
  const TorchCollisionChecker checker(plan, torch, deposit, scene);
  ResolveSettings settings;
  NullProgress progress;
  const CollisionResolution res = resolveTorchCollisions(plan, checker, settings, progress);

  const double r = 0.5 * deposit.beadWidth;
  // The untilted torch beside wall A really is too close (independent 2-D truth)...
  ASSERT_LT(sectionClearance(0.0, torch, r), torch.clearance);
  // ...and the check says so for all of the middle of wall B, and for nothing on wall A.
  for (size_t i = 0; i < wallB.front(); ++i) EXPECT_EQ(res.hits[i], 0u) << "wall A point " << i;
  for (const size_t i : wallB) {
    const double x = plan.points[i].position.x();
    if (x >= 25.0 && x <= kLength - 25.0) {
      EXPECT_EQ(res.hits[i], unsigned(kCollisionDeposit)) << "x " << x;
    }
  }

  // The smallest clearing tilt away from wall A from the 2-D section (fine bisection), plus the
  // safety angle. Leaning towards wall A only gets worse.
  double lo = 0.0, hi = degToRad(45.0);
  while (hi - lo > 1e-9) {
    const double mid = 0.5 * (lo + hi);
    (sectionClearance(-mid, torch, r) <= torch.clearance ? lo : hi) = mid;
  }
  ASSERT_LT(sectionClearance(hi + settings.safetyAngleRad, torch, r), sectionClearance(0.0, torch, r));
  const double expected = hi + settings.safetyAngleRad;
  for (const size_t i : wallB) {
    const double x = plan.points[i].position.x();
    if (x < 50.0 || x > kLength - 50.0) continue;
    EXPECT_LE(res.tiltRad[i], -expected + 1e-9) << "x " << x;
    EXPECT_GE(res.tiltRad[i], -expected - settings.toleranceRad - 1e-9) << "x " << x;
    EXPECT_GT(sectionClearance(res.tiltRad[i], torch, r), torch.clearance);
  }

  // Verified collision-free, with no tilt jump above the allowed change between neighbours. Where
  // the travel reverses (wall A's layer ends, the move to wall B) the same lean is the opposite tilt.
  EXPECT_TRUE(res.unresolved.empty());
  for (size_t i = 0; i < plan.size(); ++i) EXPECT_FALSE(checker.collides(i, res.tiltRad[i])) << "point " << i;
  for (size_t i = 0; i + 1 < plan.size(); ++i) {
    const double same = plan.points[i].tangent.dot(plan.points[i + 1].tangent) > 0.0 ? 1.0 : -1.0;
    EXPECT_LE(std::abs(same * res.tiltRad[i + 1] - res.tiltRad[i]), settings.maxTiltChangeRad + 1e-12) << i;
    const Vec3 &b0 = res.trajectory.points[i].build, &b1 = res.trajectory.points[i + 1].build;
    const double planned =
        std::acos(std::clamp(plan.points[i].build.dot(plan.points[i + 1].build), -1.0, 1.0));
    EXPECT_LE(std::acos(std::clamp(b0.dot(b1), -1.0, 1.0)), planned + settings.maxTiltChangeRad + 1e-9) << i;
  }
  // Wall A is untouched; the trajectory keeps positions and an orthonormal frame with b = n x t.
  for (size_t i = 0; i < plan.size(); ++i) {
    const TrajectoryPoint& q = res.trajectory.points[i];
    EXPECT_EQ(q.position, plan.points[i].position);
    EXPECT_NEAR((q.normal.cross(q.tangent) - q.build).norm(), 0.0, 1e-12);
    EXPECT_NEAR(q.normal.dot(q.tangent), 0.0, 1e-12);
    EXPECT_NEAR(q.build.norm(), 1.0, 1e-12);
  }
  EXPECT_EQ(res.trajectory.extra.at("torch_tilt"), res.tiltRad);
  EXPECT_EQ(res.tiltRad[0], 0.0);
  EXPECT_EQ(res.collisionCount(),
            size_t(std::count_if(res.hits.begin(), res.hits.end(), [](unsigned h) { return h; })));
}

TEST(WallResolution, AConflictBeyondTheMaximumTiltIsReportedUnresolved)
{
  std::vector<size_t> wallB;
  const Trajectory plan = plantedWalls(wallB);
  const TorchCollisionChecker checker(plan, TorchParams());
  ResolveSettings settings;
  settings.maxTiltRad = degToRad(3.0);  // far less than the wall needs
  NullProgress progress;
  const CollisionResolution res = resolveTorchCollisions(plan, checker, settings, progress);
  ASSERT_FALSE(res.unresolved.empty());
  for (const size_t i : res.unresolved) {
    EXPECT_GE(i, wallB.front());
    EXPECT_TRUE(checker.collides(i, res.tiltRad[i]));
  }
  for (size_t i = 0; i < plan.size(); ++i) EXPECT_LE(std::abs(res.tiltRad[i]), settings.maxTiltRad + 1e-12);
  // The middle of wall B is among them.
  const size_t middle = wallB[wallB.size() / 2];
  EXPECT_TRUE(std::binary_search(res.unresolved.begin(), res.unresolved.end(), middle));
}

}  // namespace
}  // namespace spira
