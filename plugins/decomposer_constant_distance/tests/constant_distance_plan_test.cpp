// decomposer.constant_distance on the source's quarter torus (004_bd0df31205c0c3c0.txt §2.3.1, validation
// V10): layers at a constant local distance, fewer than iso-v stepping needs, a kink growing on the outer
// side, and a path the deposit check finds buildable everywhere but where that kink folds the top layers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "spira/base/error.h"
#include "spira/base/segment_distance.h"
#include "spira/contour/guided_tube.h"
#include "spira/mesh/mesh_primitives.h"
#include "tube_plan_support.h"

namespace spira::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double R = 50.0, r = 15.0;  // bend and tube radius

// Distance from p to the analytic torus: centre circle of radius R about (-R, 0, 0) in y = 0.
double offTorus(const Vec3& p)
{
  const double rho = std::hypot(p.x() + R, p.z());
  return std::abs(std::hypot(rho - R, p.y()) - r);
}

// The trajectory's layers: the points of each revolution, in order.
std::map<int, std::vector<Vec3>> layersOf(const Trajectory& t)
{
  std::map<int, std::vector<Vec3>> layers;
  for (const TrajectoryPoint& p : t.points) layers[p.revolution].push_back(p.position);
  return layers;
}

// The largest turning angle of a closed layer and where it is.
std::pair<double, Vec3> worstKink(const std::vector<Vec3>& loop)
{
  double worst = 0.0;
  Vec3 at = loop.front();
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3 in = loop[i] - loop[(i + n - 1) % n], out = loop[(i + 1) % n] - loop[i];
    const double a = std::acos(std::clamp(in.normalized().dot(out.normalized()), -1.0, 1.0)) * 180.0 / kPi;
    if (a > worst) worst = a, at = loop[i];
  }
  return {worst, at};
}

TEST(ConstantDistancePlan, QuarterTorusLayersStayFiveMillimetresApartWithFewerLayersThanIsoV)
{
  const int n = 180;
  const PlanOutput plan = planTube(quarterTorus(), 5.0, 4.5, 5.5, "layers", "truncate", "", n);
  ASSERT_TRUE(plan.layers);
  // The top layers fold at their kinks: the deposit check finds the fold and nothing else.
  const size_t folds = expectFlagsOnlyAtFolds(plan, R);
  EXPECT_GT(folds, 0u);
  EXPECT_LT(folds, 30u);
  // Iso-v stepping needs the outer wall's length in steps of delta: ceil(65 pi / 2 / 5) = 21.
  const int isoV = int(std::ceil((R + r) * 0.5 * kPi / 5.0));
  EXPECT_EQ(isoV, 21);
  EXPECT_GE(plan.layers->layers, 15);
  EXPECT_LT(plan.layers->layers, isoV);

  // Whole layers (closed on their start: n + 1 points) re-measured from the path alone, against every
  // segment of the whole layer under them.
  const auto layers = layersOf(plan.spiral.trajectory);
  std::vector<std::vector<Vec3>> whole;
  for (const auto& [k, pts] : layers)
    if (pts.size() == size_t(n + 1)) whole.emplace_back(pts.begin(), pts.end() - 1);
  ASSERT_GE(whole.size(), 8u);
  double worst = 0.0, off = 0.0;
  for (size_t k = 1; k < whole.size(); ++k)
    for (const Vec3& p : whole[k]) worst = std::max(worst, std::abs(distanceToClosed(p, whole[k - 1]) - 5.0));
  for (const TrajectoryPoint& p : plan.spiral.trajectory.points) off = std::max(off, offTorus(p.position));
  EXPECT_LT(worst, 1e-3);
  // On the facets of a 2 mm mesh of the torus: within its chord error.
  EXPECT_LT(off, 0.05);

  // The kink grows on the outer side, which lags. The source's reproduction at 180 points: 44 deg at layer
  // 10, 94 at 12, 113 at 17. A layer on the facets turns at least at the mesh's corners (360 / 47 sides).
  const auto [firstKink, firstAt] = worstKink(whole[1]);
  const auto [lastKink, lastAt] = worstKink(whole.back());
  const std::vector<double>& kinks = plan.layers->kinkDeg;
  ASSERT_GE(kinks.size(), 16u);
  EXPECT_NEAR(firstKink, 360.0 / segmentsForEdge(r, 2.0), 0.5);
  EXPECT_NEAR(kinks[9], 44.0, 4.0);
  EXPECT_NEAR(kinks[11], 94.0, 4.0);
  EXPECT_NEAR(kinks.back(), 113.0, 4.0);
  EXPECT_GT(lastKink, 30.0);
  EXPECT_GT(std::hypot(lastAt.x() + R, lastAt.z()), R + 0.5 * r);
  EXPECT_NEAR(plan.layers->maxKinkDeg,
              *std::max_element(plan.layers->kinkDeg.begin(), plan.layers->kinkDeg.end()), 1e-12);
  EXPECT_GE(plan.layers->maxKinkDeg, lastKink);
  std::printf(
      "quarter torus, delta 5: %d layers (iso-v %d), delta %.4f .. %.4f, kink %.1f deg (layer 1) .. %.1f deg "
      "(last whole layer), %d arcs, %zu points at folds\n",
      plan.layers->layers, isoV, plan.layers->deltaMin, plan.layers->deltaMax, firstKink, lastKink,
      plan.layers->arcStarts, folds);
  for (size_t k = 0; k < plan.layers->kinkDeg.size(); ++k) std::printf(" %.1f", plan.layers->kinkDeg[k]);
  std::printf(" (kink per layer, deg)\n");
}

TEST(ConstantDistancePlan, LayersStartStaggeredOneArcEach)
{
  const PlanOutput plan = planTube(quarterTorus(), 5.0, 4.5, 5.5, "layers", "truncate", "", 180);
  ASSERT_TRUE(plan.layers);
  const Trajectory& t = plan.spiral.trajectory;
  // One arc per sub-path; each whole layer's start is 137.5 deg further round than the one below.
  std::map<int, size_t> firstOf;
  int arcs = 0;
  for (size_t q = 0; q < t.size(); ++q)
    if (q == 0 || t.points[q].path != t.points[q - 1].path) {
      ++arcs;
      if (!firstOf.count(t.points[q].revolution)) firstOf[t.points[q].revolution] = q;
    }
  EXPECT_EQ(arcs, plan.layers->arcStarts);
  EXPECT_GE(arcs, plan.layers->layers);
  for (int k = 1; k < 6; ++k) {
    const int step = (t.points[firstOf[k]].generatrix - t.points[firstOf[k - 1]].generatrix + 180) % 180;
    EXPECT_NEAR(step * 2.0, 137.5, 2.0) << "layer " << k;
  }
}

TEST(ConstantDistancePlan, OneSpiralThroughTheLayersLaysAConstantDeposit)
{
  const PlanOutput plan = planTube(quarterTorus(), 5.0, 4.5, 5.5, "spiral", "truncate", "", 180);
  ASSERT_TRUE(plan.layers);
  expectFlagsOnlyAtFolds(plan, R);
  const SpiralReport& s = plan.spiral.report;
  // Between its start-up and its end the spiral climbs one layer per revolution at delta.
  EXPECT_GT(s.heightMin, 4.8);
  EXPECT_LT(s.heightMax, 5.3);
  EXPECT_LE(plan.deposits.heightMax, 5.5 + 0.025);
  EXPECT_EQ(plan.deposits.counts[int(DepositDefect::Thin)], 0u);
  // The truncated end cuts the last revolutions: one arc for the spiral and one per piece after it.
  EXPECT_GT(plan.layers->arcStarts, 1);
  EXPECT_EQ(plan.spiral.trajectory.points.front().path, 0);
  std::printf("spiral: %d revolutions, %zu points, deposit %.3f .. %.3f mm (check %.3f .. %.3f), %d arcs\n",
              s.nRevolutions, s.nPoints, s.heightMin, s.heightMax, plan.deposits.heightMin,
              plan.deposits.heightMax, plan.layers->arcStarts);
}

TEST(ConstantDistancePlan, AnEndTooSlantedForTheWindowIsRefusedWithTheFix)
{
  try {
    planTube(quarterTorus(), 5.0, 4.5, 5.5, "layers", "modulate", "", 90);
    FAIL() << "a quarter bend cannot end on its edge within +/- 10 %";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot end on the upper edge"), std::string::npos) << e.what();
    EXPECT_NE(e.hint().find("--end truncate"), std::string::npos) << e.hint();
  }
}

}  // namespace
}  // namespace spira::test

namespace spira::test {
namespace {

// The source's generalised tube (004_bd0df31205c0c3c0.txt Eq. 2.29, validation V34): a guide curving in
// x and y as it rises 40 mm, a radius waving between 4 and 6 mm, meshed at 0.2 mm rows and 5 deg round.
TriangleMesh eq229Tube()
{
  const auto guide = [](double t) { return Vec3((0.005 * t * t * t - 0.22 * t * t) / 6.0, 0.02 * t * t, t); };
  const auto radius = [](double t) { return 5.0 + std::cos(8.0 * kPi * t / 40.0); };
  const TubeSurface s = guidedTube(guide, radius, 0.0, 40.0);
  return makeTubeSurface([&](double u, double v) { return s.at(40.0 * u, v); }, 72, 200);
}

TEST(ConstantDistancePlan, TheEq229TubeIsPlannedInLayersOneMillimetreApart)
{
  const PlanOutput plan = planTube(eq229Tube(), 1.0, 0.9, 1.1, "layers", "truncate", "", 120);
  ASSERT_TRUE(plan.layers);
  // Its guide is 56.15 mm long: about as many layers at 1 mm, the narrow waists and the bends taking a
  // few more on their outer side.
  EXPECT_GE(plan.layers->layers, 50);
  EXPECT_LE(plan.layers->layers, 64);
  EXPECT_NEAR(plan.layers->deltaMin, 1.0, 1e-3);
  EXPECT_NEAR(plan.layers->deltaMax, 1.0, 1e-3);
  // The deposit check flags only beads a little thick at the layers' kinks (the source's thicker wall
  // there), a handful of the path's points.
  for (const DepositFlag& f : plan.deposits.flags) {
    const TrajectoryPoint& p = plan.spiral.trajectory.points[f.point];
    EXPECT_EQ(f.kind, DepositDefect::Thick) << "point " << f.point;
    EXPECT_LT(f.height, 1.35) << "point " << f.point;
    EXPECT_GT(plan.layers->kinkDeg[size_t(p.revolution)], 20.0) << "point " << f.point;
  }
  EXPECT_LT(plan.deposits.flags.size(), plan.spiral.trajectory.size() / 100);
  std::printf(
      "Eq. 2.29 tube at 1 mm: %d layers, kink up to %.1f deg, %d arcs, deposit check %.3f .. %.3f mm, %zu "
      "thick at kinks\n",
      plan.layers->layers, plan.layers->maxKinkDeg, plan.layers->arcStarts, plan.deposits.heightMin,
      plan.deposits.heightMax, plan.deposits.flags.size());
}

}  // namespace
}  // namespace spira::test
