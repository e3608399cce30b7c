#include <cmath>

#include <gtest/gtest.h>

#include "decomposer_envelope/skeleton_fit.h"
#include "spira/base/error.h"
#include "spira/base/units.h"

namespace spira {
namespace {

// A straight leaning chain, its nodes pushed sideways by +-j alternately (the contraction's
// jitter) and unevenly spaced in z.
Polyline jitteredLine(const Vec3& origin, const Vec3& slope, double j, size_t n)
{
  Polyline c;
  for (size_t k = 0; k < n; ++k) {
    const double z = 60.0 * std::pow(static_cast<double>(k) / static_cast<double>(n - 1), 1.3);
    const double side = (k % 2 ? 1.0 : -1.0) * j;
    c.emplace_back(origin.x() + slope.x() * z + side, origin.y() + slope.y() * z - 0.5 * side, z);
  }
  return c;
}

TEST(SkeletonFit, IsExactOnAStraightChain)
{
  const Vec3 origin(3, -2, 0), slope(0.25, -0.1, 0);
  const HeightFit fit = fitChainByHeight(jitteredLine(origin, slope, 0.0, 31), 10.0);
  ASSERT_EQ(fit.points.size(), 31u);
  EXPECT_NEAR(fit.points.front().z(), 0.0, 1e-12);
  EXPECT_NEAR(fit.points.back().z(), 60.0, 1e-12);
  for (const Vec3& p : fit.points) {
    EXPECT_NEAR(p.x(), origin.x() + slope.x() * p.z(), 1e-9);
    EXPECT_NEAR(p.y(), origin.y() + slope.y() * p.z(), 1e-9);
  }
  EXPECT_NEAR(fit.lineSlope.x(), slope.x(), 1e-12);
  EXPECT_NEAR(fit.lineSlope.y(), slope.y(), 1e-12);
  EXPECT_LT(largestOffsetFromLine(fit), 1e-9);
}

TEST(SkeletonFit, DropsTheJitterOfTheNodes)
{
  const Vec3 origin(0, 0, 0), slope(0.1, 0.05, 0);
  const double jitter = 0.5;
  const HeightFit fit = fitChainByHeight(jitteredLine(origin, slope, jitter, 40), 15.0);
  double worst = 0.0, inner = 0.0;
  for (size_t k = 0; k < fit.points.size(); ++k) {
    const Vec3& p = fit.points[k];
    const double off = std::hypot(p.x() - slope.x() * p.z(), p.y() - slope.y() * p.z());
    worst = std::max(worst, off);
    if (p.z() > 15.0 && p.z() < 45.0) inner = std::max(inner, off);
  }
  // The raw nodes stray 0.56 mm. Within a window of the ends the fit is one-sided and keeps more.
  const double raw = jitter * std::hypot(1.0, 0.5);
  EXPECT_LT(worst, 0.35 * raw);
  EXPECT_LT(inner, 0.1 * raw);
  EXPECT_NEAR(fit.lineSlope.x(), slope.x(), 2e-3);
  EXPECT_NEAR(fit.lineSlope.y(), slope.y(), 2e-3);
}

TEST(SkeletonFit, FollowsABentChain)
{
  // A quarter-circle skeleton of radius 80 mm rising 0..56.6 mm: x = 80 - sqrt(80^2 - z^2).
  const double rho = 80.0;
  Polyline c;
  for (int k = 0; k <= 40; ++k) {
    const double a = 0.25 * kPi * k / 40.0;
    c.emplace_back(rho - rho * std::cos(a), 0.0, rho * std::sin(a));
  }
  const double h = 8.0;
  const HeightFit fit = fitChainByHeight(c, h);
  // A local line cuts the bend's corner by x''/2 times the window's second moment (0.143 h^2 for
  // the tricube-cubed weights): 0.06 mm at the foot, 0.16 mm at the top where the bend is tighter.
  for (const Vec3& p : fit.points) {
    const double q = rho * rho - p.z() * p.z();
    const double curvature = rho * rho / (q * std::sqrt(q));  // x''(z)
    EXPECT_NEAR(p.x(), rho - std::sqrt(q), 0.1 * curvature * h * h) << "z = " << p.z();
  }
  // A 45-degree bend: 6.1 mm from its chord, so neither a line nor the vertical stands in for it.
  EXPECT_GT(largestOffsetFromLine(fit), 2.0);
  EXPECT_GT(largestOffsetFromVertical(fit, Vec3::Zero(), 0.0, 56.6), 20.0);
}

TEST(SkeletonFit, RefusesAChainThatDoesNotRise)
{
  EXPECT_THROW(fitChainByHeight({Vec3(0, 0, 1), Vec3(5, 0, 1)}, 5.0), InputError);
  EXPECT_THROW(fitChainByHeight({Vec3(0, 0, 1)}, 5.0), InputError);
}

}  // namespace
}  // namespace spira
