// The numerical frame from the path alone (Chalvin Eq. 2.36, validation case V12): on the source's
// quarter torus laid at 5 mm with 500 points per layer, the facet normals against the torus's own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "spira/path/facet_normals.h"
#include "tube_plan_support.h"

namespace spira::test {
namespace {

constexpr double kBend = 50.0;

// The quarter torus's normal at p: away from the nearest point of its centre circle (radius 50 about
// (-50, 0, 0) in the xz plane).
Vec3 torusNormal(const Vec3& p)
{
  const Vec3 q(p.x() + kBend, 0.0, p.z());
  const Vec3 centre = Vec3(-kBend, 0.0, 0.0) + kBend * q.normalized();
  return (p - centre).normalized();
}

TEST(FacetFrame, NormalsFromThePathMatchTheTorusAsTheSourceFinds)
{
  const PlanOutput plan = planTube(quarterTorus(), 5.0, 4.5, 5.5, "layers", {}, {}, 500);
  std::map<int, Polyline> byLayer;
  std::map<int, std::vector<Vec3>> planned;  // the plan's normals, from the part's facets
  for (const TrajectoryPoint& p : plan.spiral.trajectory.points) {
    byLayer[p.revolution].push_back(p.position);
    planned[p.revolution].push_back(p.normal);
  }
  // Whole layers only: the top ones are cut by the tube's end face.
  std::vector<Polyline> layers;
  std::vector<std::vector<Vec3>> plannedNormals;
  for (auto& [k, layer] : byLayer) {
    if (layer.size() < 490) break;
    layers.push_back(std::move(layer));
    plannedNormals.push_back(std::move(planned[k]));
  }
  ASSERT_GE(layers.size(), 10u);
  const std::vector<std::vector<Vec3>> normals = facetNormals(layers);
  double sum = 0.0, worst = 0.0, plannedSum = 0.0;
  size_t count = 0;
  for (size_t k = 0; k < layers.size(); ++k)
    for (size_t v = 0; v < layers[k].size(); ++v) {
      const Vec3 truth = torusNormal(layers[k][v]);
      const double e = (normals[k][v] - truth).norm();
      sum += e, worst = std::max(worst, e), ++count;
      plannedSum += (plannedNormals[k][v] - truth).norm();
    }
  const double mu = sum / double(count), plannedMu = plannedSum / double(count);
  std::printf(
      "quarter torus, %zu whole layers, %zu points: facet normals mu = %.4f (the source: about 0.04), "
      "worst %.4f; the plan's own normals mu = %.4f\n",
      layers.size(), count, mu, worst, plannedMu);
  EXPECT_LT(mu, 0.04);
  EXPECT_LT(worst, 0.2);
  // The plan takes its normals from the part's surface, closer to the truth than the path alone gives.
  EXPECT_LT(plannedMu, 0.5 * mu);
}

}  // namespace
}  // namespace spira::test
