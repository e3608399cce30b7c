// Layers at a constant local distance on analytic tubes (004_bd0df31205c0c3c0.txt §2.3.1, the seed
// spec's reproduction on the quarter torus): every point at delta from the layer below, fewer layers
// than iso-v stepping, the kink growing on the lagging outer side, and plain offsets on a cylinder.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "spira/base/error.h"
#include "spira/contour/constant_distance.h"
#include "spira/contour/guided_tube.h"
#include "spira/contour/meshed_tube.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Eq. 2.28: the guide g(t) = (R cos t - R, 0, R sin t), a circle of radius r around it; v = 0 on the
// outer side (farthest from the torus axis), which lags.
TubeSurface quarterTorus(double R, double r)
{
  TubeSurface s;
  s.at = [R, r](double t, double v) {
    const Vec3 centre(R * std::cos(t) - R, 0.0, R * std::sin(t));
    const Vec3 outward(std::cos(t), 0.0, std::sin(t));
    return Vec3(centre + r * (std::cos(v) * outward + std::sin(v) * Vec3::UnitY()));
  };
  s.t0 = 0.0;
  s.tEnd = kPi;  // the guide extended past the nominal end, pi / 2
  return s;
}

ConstantDistanceLayers torusLayers(int points)
{
  ConstantDistanceSettings settings;
  settings.delta = 5.0;
  settings.pointsPerLayer = points;
  return constantDistanceLayers(quarterTorus(50.0, 15.0), std::vector<double>(size_t(points), 0.0), kPi / 2,
                                settings);
}

// The largest |distance to the layer below - delta| over every point of every layer after the first.
double worstDistanceError(const ConstantDistanceLayers& layers, double delta)
{
  double worst = 0.0;
  for (size_t n = 1; n < layers.points.size(); ++n)
    for (const Vec3& p : layers.points[n])
      worst = std::max(worst, std::abs(distanceToClosedLayer(p, layers.points[n - 1], 0, 0) - delta));
  return worst;
}

TEST(ConstantDistance, QuarterTorusLayersAreFiveMillimetresApartInFewerStepsThanIsoV)
{
  const ConstantDistanceLayers layers = torusLayers(360);
  ASSERT_TRUE(layers.complete);
  const int steps = int(layers.t.size()) - 1;
  // Iso-v stepping must keep the outer side (R + r from the axis) within delta: pi/2 (R + r) / delta.
  const int isoV = int(std::ceil(kPi / 2 * (50.0 + 15.0) / 5.0));
  EXPECT_EQ(isoV, 21);
  EXPECT_EQ(steps, 17);
  const double worst = worstDistanceError(layers, 5.0);
  EXPECT_LT(worst, 1e-3);
  // Each point advances along its own generatrix.
  for (size_t n = 1; n < layers.t.size(); ++n)
    for (size_t i = 0; i < layers.t[n].size(); ++i) ASSERT_GT(layers.t[n][i], layers.t[n - 1][i]);
  std::printf("quarter torus R 50 r 15, delta 5: %d layers (iso-v %d), worst |delta - 5| %.2e mm\n", steps,
              isoV, worst);
}

// The wavefront shock of the seed spec's table: a few degrees on the first layers, tens of degrees
// by layer 10, over 90 by the last, always on the outer side (v = 0).
TEST(ConstantDistance, KinkGrowsOnTheLaggingOuterSide)
{
  const ConstantDistanceLayers layers = torusLayers(180);
  ASSERT_GE(layers.points.size(), 18u);
  std::printf("max turning angle per layer (180 points):");
  for (size_t n = 1; n < layers.points.size(); ++n) std::printf(" %.0f", maxTurningAngle(layers.points[n]));
  std::printf("\n");
  for (size_t n = 1; n <= 5; ++n) EXPECT_LT(maxTurningAngle(layers.points[n]), 3.0) << n;
  EXPECT_GT(maxTurningAngle(layers.points[10]), 20.0);
  EXPECT_GT(maxTurningAngle(layers.points[17]), 90.0);
  const std::vector<Vec3>& last = layers.points[17];
  size_t at = 0;
  double sharpest = 0.0;
  for (size_t i = 0; i < last.size(); ++i) {
    const Vec3 in = last[i] - last[(i + last.size() - 1) % last.size()],
               out = last[(i + 1) % last.size()] - last[i];
    const double angle = std::acos(std::clamp(in.normalized().dot(out.normalized()), -1.0, 1.0));
    if (angle > sharpest) sharpest = angle, at = i;
  }
  EXPECT_TRUE(at <= 2 || at >= last.size() - 2) << "the kink is at point " << at;
}

// On a straight cylinder the constant-distance layers are the plain offsets t = n delta, as iso-value
// slicing gives them.
TEST(ConstantDistance, StraightCylinderLayersAreThePlainOffsets)
{
  TubeSurface cylinder;
  cylinder.at = [](double t, double v) { return Vec3(10.0 * std::cos(v), 10.0 * std::sin(v), t); };
  cylinder.t0 = 0.0;
  cylinder.tEnd = 40.0;
  ConstantDistanceSettings settings;
  settings.delta = 2.0;
  settings.pointsPerLayer = 90;
  const ConstantDistanceLayers layers =
      constantDistanceLayers(cylinder, std::vector<double>(90, 0.0), 30.0, settings);
  ASSERT_TRUE(layers.complete);
  ASSERT_EQ(layers.t.size(), 16u);
  for (size_t n = 0; n < layers.t.size(); ++n)
    for (double t : layers.t[n]) ASSERT_NEAR(t, 2.0 * double(n), 1e-5) << n;
}

TEST(ConstantDistance, StopsWhereTheSurfaceEndsAndRefusesBadInput)
{
  TubeSurface cylinder;
  cylinder.at = [](double t, double v) { return Vec3(10.0 * std::cos(v), 10.0 * std::sin(v), t); };
  cylinder.tEnd = 7.0;
  ConstantDistanceSettings settings;
  settings.pointsPerLayer = 36;
  const ConstantDistanceLayers short_ =
      constantDistanceLayers(cylinder, std::vector<double>(36, 0.0), 6.5, settings);
  EXPECT_FALSE(short_.complete);
  EXPECT_EQ(short_.t.size(), 4u);  // 0, 2, 4, 6: 8 lies past the surface's end

  EXPECT_THROW(constantDistanceLayers(cylinder, std::vector<double>(36, 0.0), 8.0, settings), InputError);
  EXPECT_THROW(constantDistanceLayers(cylinder, std::vector<double>(35, 0.0), 6.0, settings), InputError);
  settings.delta = 0.0;
  EXPECT_THROW(constantDistanceLayers(cylinder, std::vector<double>(36, 0.0), 6.0, settings), InputError);
  settings.delta = 2.0;
  settings.pointsPerLayer = 4;
  EXPECT_THROW(constantDistanceLayers(cylinder, std::vector<double>(4, 0.0), 6.0, settings), InputError);
}

// V7, the perpendicular slicing the method replaces: planes through the torus axis every 0.100042 rad
// put the layers 3.500 mm apart on the inner side and 6.500 mm on the outer one (+-30 %).
TEST(ConstantDistance, PerpendicularSlicingOfTheTorusSpreadsTheDistanceThirtyPercent)
{
  const TubeSurface torus = quarterTorus(50.0, 15.0);
  const int points = 720;
  const auto layer = [&](double u) {
    std::vector<Vec3> l;
    for (int i = 0; i < points; ++i) l.push_back(torus.at(u, 2.0 * kPi * i / points));
    return l;
  };
  const double du = 0.100042;
  double lo = 1e300, hi = 0.0;
  for (int n = 1; n * du <= kPi / 2; ++n) {
    const std::vector<Vec3> below = layer((n - 1) * du), here = layer(n * du);
    for (const Vec3& p : here) {
      const double d = distanceToClosedLayer(p, below, 0, 0);
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
  }
  EXPECT_NEAR(lo, 3.500, 2e-3);
  EXPECT_NEAR(hi, 6.500, 2e-3);
}

// V34, the source's generalised tube (Eq. 2.29): a twisting guide 56.15 mm long, a radius waving
// between 4 and 6 mm four times. Planned with delta 1 mm on a parallel-transported frame, every point
// lies 1.000 mm from the layer below, up to the guide's nominal end.
TEST(ConstantDistance, TheSourcesWavyTubeIsLaidAtOneMillimetre)
{
  const auto guide = [](double t) { return Vec3((0.005 * t * t * t - 0.22 * t * t) / 6.0, 0.02 * t * t, t); };
  const auto radius = [](double t) { return 5.0 + std::cos(8.0 * kPi * t / 40.0); };
  EXPECT_NEAR(guideLength(guide, 0.0, 40.0), 56.15, 0.01);
  const TubeSurface tube = guidedTube(guide, radius, 0.0, 48.0);
  ConstantDistanceSettings settings;
  settings.delta = 1.0;
  settings.pointsPerLayer = 180;
  const ConstantDistanceLayers layers =
      constantDistanceLayers(tube, std::vector<double>(180, 0.0), 40.0, settings);
  ASSERT_TRUE(layers.complete);
  const double worst = worstDistanceError(layers, 1.0);
  EXPECT_LT(worst, 1e-3);
  // Each point lies on the tube: at its radius from the guide point of its own t.
  for (size_t i = 0; i < 180; i += 7) {
    const double t = layers.t.back()[i];
    EXPECT_NEAR((layers.points.back()[i] - guide(t)).norm(), radius(t), 1e-9);
  }
  std::printf("Eq. 2.29 tube, delta 1: %zu layers, worst |delta - 1| %.2e mm\n", layers.t.size() - 1, worst);
}

// The parallel-transported frame of a planar guide is the analytic one: swept along the torus's guide, it
// gives the analytic torus's layers.
TEST(ConstantDistance, GuidedTubeOnTheTorusGuideGivesTheAnalyticLayers)
{
  const auto guide = [](double t) { return Vec3(50.0 * std::cos(t) - 50.0, 0.0, 50.0 * std::sin(t)); };
  const TubeSurface swept = guidedTube(
      guide, [](double) { return 15.0; }, 0.0, kPi);
  const TubeSurface torus = quarterTorus(50.0, 15.0);
  double offset = 1e300;  // the two frames may differ by a fixed turn about the guide
  for (double v0 = 0.0; v0 < 2.0 * kPi; v0 += kPi / 2)
    offset = std::min(offset, (swept.at(0.0, 0.0) - torus.at(0.0, v0)).norm());
  EXPECT_LT(offset, 1e-9);
  ConstantDistanceSettings settings;
  settings.delta = 5.0;
  settings.pointsPerLayer = 360;
  const ConstantDistanceLayers layers =
      constantDistanceLayers(swept, std::vector<double>(360, 0.0), kPi / 2, settings);
  EXPECT_EQ(layers.t.size() - 1, 17u);
}

// On the part's own facets (40,000 triangles) the layers are still 5.000 mm apart, as many as on the
// analytic torus, and within the facets' sag of the analytic layers.
TEST(ConstantDistance, MeshedTorusGivesTheAnalyticLayersWithinTheFacetSag)
{
  const auto guide = [](double t) { return Vec3(50.0 * std::cos(t) - 50.0, 0.0, 50.0 * std::sin(t)); };
  // Up to 3 rad, well past the nominal end: the inner side runs ahead.
  const TriangleMesh mesh = makeBentTube(50.0, 15.0, 3.0, 200, 100);
  ASSERT_EQ(mesh.faceCount(), 40000u);
  const TubeSurface tube = meshedTube(mesh, guide, 0.0, 3.0, 40.0);
  ConstantDistanceSettings settings;
  settings.delta = 5.0;
  settings.pointsPerLayer = 360;
  const ConstantDistanceLayers meshed =
      constantDistanceLayers(tube, std::vector<double>(360, 0.0), kPi / 2, settings);
  ASSERT_TRUE(meshed.complete);
  EXPECT_LT(worstDistanceError(meshed, 5.0), 1e-3);
  const ConstantDistanceLayers analytic = torusLayers(360);
  ASSERT_EQ(meshed.points.size(), analytic.points.size());
  // The frames of the two surfaces may start a quarter turn apart; compare each meshed point with the
  // nearest analytic point of the same layer.
  const double sag = 15.0 * (1.0 - std::cos(kPi / 200));  // the facets' depth under the circle
  double worst = 0.0;
  for (size_t n = 0; n < meshed.points.size(); ++n)
    for (const Vec3& p : meshed.points[n])
      worst = std::max(worst, distanceToClosedLayer(p, analytic.points[n], 0, 0));
  std::printf(
      "meshed torus (40,000 triangles): %zu layers, farthest from the analytic layers %.4f mm (sag %.4f)\n",
      meshed.points.size() - 1, worst, sag);
  EXPECT_LT(worst, 0.02);
}

// A centre line given as 31 points (a skeleton's or a user's CSV) guides the meshed tube as well as
// the analytic arc: the same layers, 5.000 mm apart.
TEST(ConstantDistance, PolylineGuideThroughTheCentreLineGivesTheSameLayers)
{
  std::vector<Vec3> line;
  for (int k = 0; k <= 30; ++k) {
    const double t = 3.0 * k / 30;
    line.emplace_back(50.0 * std::cos(t) - 50.0, 0.0, 50.0 * std::sin(t));
  }
  const auto guide = polylineGuide(line);
  const TriangleMesh mesh = makeBentTube(50.0, 15.0, 3.0, 200, 100);
  ConstantDistanceSettings settings;
  settings.delta = 5.0;
  settings.pointsPerLayer = 360;
  // The polyline's length stands for the arc's: the nominal end, pi/2 of 3 rad along it.
  double length = 0.0;
  for (size_t k = 1; k < line.size(); ++k) length += (line[k] - line[k - 1]).norm();
  // The guide starts below the base (its end tangent is a chord, not square to the base ring): the
  // first layer is the tube's own base edge.
  const TubeSurface tube = meshedTube(mesh, guide, -2.0, length, 40.0);
  const std::vector<double> base = baseLayer(tube, 360, -2.0, 2.0);
  for (size_t i = 0; i < base.size(); i += 30)
    EXPECT_NEAR(tube.at(base[i], 2.0 * kPi * i / 360).z(), 0.0, 1e-4);
  const ConstantDistanceLayers layers =
      constantDistanceLayers(tube, base, length * (kPi / 2) / 3.0, settings);
  ASSERT_TRUE(layers.complete);
  EXPECT_EQ(layers.t.size() - 1, 17u);
  EXPECT_LT(worstDistanceError(layers, 5.0), 1e-3);
  EXPECT_THROW(polylineGuide({Vec3::Zero()}), InputError);
  EXPECT_THROW(polylineGuide({Vec3::Zero(), Vec3::Zero()}), InputError);
}

// A meshed tube that ends at its nominal end: the inner side, running ahead, leaves the mesh before the
// outer one reaches the end. The layers stop there as incomplete, every point laid on the mesh.
TEST(ConstantDistance, MeshedTubeEndingAtItsEndStopsWithEveryPointOnTheMesh)
{
  const auto guide = [](double t) { return Vec3(50.0 * std::cos(t) - 50.0, 0.0, 50.0 * std::sin(t)); };
  const TriangleMesh mesh = makeBentTube(50.0, 15.0, kPi / 2, 120, 60);
  ConstantDistanceSettings settings;
  settings.delta = 5.0;
  settings.pointsPerLayer = 120;
  const ConstantDistanceLayers layers = constantDistanceLayers(
      meshedTube(mesh, guide, 0.0, 3.0, 40.0), std::vector<double>(120, 0.0), kPi / 2, settings);
  EXPECT_FALSE(layers.complete);
  EXPECT_GE(layers.points.size(), 10u);
  for (const auto& layer : layers.points)
    for (const Vec3& p : layer) ASSERT_TRUE(p.allFinite());
  EXPECT_LT(worstDistanceError(layers, 5.0), 1e-3);
}

TEST(ConstantDistance, MeshedTubeRefusesAGuideOutsideThePart)
{
  const TriangleMesh mesh = makeBentTube(50.0, 15.0, 3.0, 40, 20);
  const auto outside = [](double t) { return Vec3(200.0, 0.0, t); };
  EXPECT_THROW(meshedTube(mesh, outside, 0.0, 10.0, 5.0), InputError);
  EXPECT_THROW(meshedTube(TriangleMesh{}, outside, 0.0, 10.0, 5.0), InputError);
}

}  // namespace
}  // namespace spira
