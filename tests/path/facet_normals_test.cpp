// Normals from a layered path alone (facet_normals.h): exact on a cylinder's circles, oriented so that
// b = n x t climbs, and refused with the reason for too few layers or points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/path/facet_normals.h"

namespace spira {
namespace {

// Layers of `points` points on circles, each turned by `stagger` of a step from the one below.
std::vector<Polyline> circles(double radius, double spacing, int layers, int points, double stagger = 0.0)
{
  std::vector<Polyline> out(layers);
  for (int k = 0; k < layers; ++k)
    for (int v = 0; v < points; ++v) {
      const double a = 2.0 * kPi * (v + stagger * k) / points;
      out[k].push_back(Vec3(radius * std::cos(a), radius * std::sin(a), spacing * k));
    }
  return out;
}

TEST(FacetNormals, OnACylinderTheyAreRadialAndTheBuildDirectionClimbs)
{
  const std::vector<Polyline> layers = circles(40.0, 2.0, 6, 90);
  const auto normals = facetNormals(layers);
  ASSERT_EQ(normals.size(), layers.size());
  // Each point's neighbours below and above lie straight below and above it, and its chord M[v-1] M[v+1]
  // passes inside the circle by s = R (1 - cos(2 pi / 90)): one facet leans in, the other out, by
  // atan(s / spacing). Their mean is radial; the first and last layers, with one facet, lean by that angle.
  const double lean = std::atan(40.0 * (1.0 - std::cos(2.0 * kPi / 90.0)) / 2.0);
  for (size_t k = 0; k < layers.size(); ++k) {
    const size_t n = layers[k].size();
    const bool end = k == 0 || k + 1 == layers.size();
    for (size_t v = 0; v < n; ++v) {
      const Vec3& p = layers[k][v];
      const Vec3 radial = Vec3(p.x(), p.y(), 0.0).normalized();
      EXPECT_NEAR(std::acos(std::min(1.0, normals[k][v].dot(radial))), end ? lean : 0.0, 1e-6)
          << k << " " << v;
      const Vec3 t = (layers[k][(v + 1) % n] - layers[k][(v + n - 1) % n]).normalized();
      EXPECT_NEAR(normals[k][v].cross(t).z(), std::cos(end ? lean : 0.0), 1e-12);
    }
  }
  // Staggered, a point's nearest points below and above lie on chords of those layers, inside their
  // circles: no normal leans further than the end layers' facets above.
  const std::vector<Polyline> staggered = circles(40.0, 2.0, 6, 90, 0.37);
  const auto leaning = facetNormals(staggered);
  for (size_t k = 0; k < staggered.size(); ++k)
    for (size_t v = 0; v < staggered[k].size(); ++v) {
      const Vec3& p = staggered[k][v];
      EXPECT_LT(std::acos(std::min(1.0, leaning[k][v].dot(Vec3(p.x(), p.y(), 0.0).normalized()))), lean);
    }
  // Walked the other way round the normals turn inwards, and b still climbs.
  std::vector<Polyline> reversed = layers;
  for (Polyline& layer : reversed) std::reverse(layer.begin(), layer.end());
  const auto inward = facetNormals(reversed);
  EXPECT_NEAR(inward[2][0].dot(Vec3(reversed[2][0].x(), reversed[2][0].y(), 0).normalized()), -1.0, 1e-12);
}

TEST(FacetNormals, TooFewLayersOrPointsAreRefused)
{
  EXPECT_THROW(facetNormals(circles(40.0, 2.0, 1, 90)), InputError);
  std::vector<Polyline> layers = circles(40.0, 2.0, 3, 90);
  layers[1].resize(2);
  try {
    facetNormals(layers);
    FAIL() << "a two-point layer was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("layer 1 has 2 points"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spira
