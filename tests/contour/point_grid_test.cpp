#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "spira/contour/point_grid.h"

namespace spira {
namespace {

size_t bruteNearest(const std::vector<Vec3>& pts, const Vec3& q)
{
  size_t best = 0;
  for (size_t i = 1; i < pts.size(); ++i)
    if ((pts[i] - q).squaredNorm() < (pts[best] - q).squaredNorm()) best = i;
  return best;
}

TEST(PointGrid, MatchesALinearScan)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-10, 10);
  // A flat ring (zero height, like an iso-contour) and a random cloud.
  std::vector<Vec3> ring, cloud;
  for (int i = 0; i < 500; ++i) ring.emplace_back(8 * std::cos(i * 0.01257), 8 * std::sin(i * 0.01257), 3.0);
  for (int i = 0; i < 800; ++i) cloud.emplace_back(u(rng), u(rng), u(rng));
  for (const auto* pts : {&ring, &cloud}) {
    for (double cell : {0.05, 0.5, 4.0, 100.0}) {
      const PointGrid grid(*pts, cell);
      for (int i = 0; i < 400; ++i) {
        // Near the set, off its plane, and far away.
        const double scale = i < 200 ? 1.0 : (i < 350 ? 3.0 : 1000.0);
        const Vec3 q(scale * u(rng), scale * u(rng), 3.0 + scale * 0.1 * u(rng));
        const size_t a = grid.nearest(q), b = bruteNearest(*pts, q);
        EXPECT_DOUBLE_EQ(((*pts)[a] - q).norm(), ((*pts)[b] - q).norm()) << "cell " << cell << " query " << i;
      }
    }
  }
  // Ties go to the lowest index: two copies of the same point.
  const PointGrid twin({Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(1, 1, 1)}, 0.3);
  EXPECT_EQ(twin.nearest(Vec3(1.1, 1, 1)), 0u);
  EXPECT_EQ(PointGrid({Vec3(2, 2, 2)}, 1.0).nearest(Vec3(-50, 0, 9)), 0u);
}

}  // namespace
}  // namespace spira
