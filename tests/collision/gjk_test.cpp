#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "spira/collision/basic_shapes.h"
#include "spira/collision/gjk.h"

namespace spira {
namespace {

TEST(Gjk, SkewSegmentsMeetAtTheCommonPerpendicular)
{
  const SegmentShape a(Vec3(0, 0, 0), Vec3(10, 0, 0));
  const SegmentShape b(Vec3(5, 3, 4), Vec3(5, 3, -4));
  const GjkResult r = gjkDistance(a, b);
  EXPECT_NEAR(r.distance, 3.0, 1e-9);
  EXPECT_NEAR((r.pointA - Vec3(5, 0, 0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((r.pointB - Vec3(5, 3, 0)).norm(), 0.0, 1e-9);
  EXPECT_FALSE(r.intersecting);
}

TEST(Gjk, ParallelSegmentsMeetAtTheirNearEnds)
{
  const SegmentShape a(Vec3(0, 0, 0), Vec3(10, 0, 0));
  const SegmentShape b(Vec3(12, 2, 0), Vec3(20, 2, 0));
  EXPECT_NEAR(gjkDistance(a, b).distance, std::sqrt(8.0), 1e-9);
}

TEST(Gjk, PointAboveTheInteriorAndBeyondTheHypotenuseOfATriangle)
{
  const TriangleShape t(Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, 0));
  const SegmentShape above(Vec3(2, 2, 5), Vec3(2, 2, 5));
  EXPECT_NEAR(gjkDistance(t, above).distance, 5.0, 1e-9);
  const SegmentShape beyond(Vec3(10, 10, 0), Vec3(10, 10, 0));
  EXPECT_NEAR(gjkDistance(t, beyond).distance, 10.0 / std::sqrt(2.0), 1e-9);
}

TEST(Gjk, SeparatedBoxesAndOverlappingTriangles)
{
  BoundingBox a, b;
  a.extend(Vec3(0, 0, 0));
  a.extend(Vec3(1, 1, 1));
  b.extend(Vec3(3, 0, 5));
  b.extend(Vec3(4, 1, 6));
  EXPECT_NEAR(gjkDistance(BoxShape(a), BoxShape(b)).distance, std::sqrt(20.0), 1e-9);

  const TriangleShape t1(Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, 0));
  const TriangleShape t2(Vec3(2, 2, -3), Vec3(2, 2, 3), Vec3(8, -5, 0));  // pierces t1
  const GjkResult r = gjkDistance(t1, t2);
  EXPECT_TRUE(r.intersecting);
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_TRUE(gjkWithin(t1, t2, 0.0));
}

// Brute-force truth: the nearest pair among dense samples of a segment and a triangle. Sampling
// overestimates by at most the sample spacing, and can never underestimate.
double sampledDistance(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c, int n)
{
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) {
    const Vec3 s = p + (q - p) * (double(i) / n);
    for (int u = 0; u <= n; ++u)
      for (int v = 0; u + v <= n; ++v) {
        const Vec3 x = a + (b - a) * (double(u) / n) + (c - a) * (double(v) / n);
        best = std::min(best, (s - x).norm());
      }
  }
  return best;
}

TEST(Gjk, RandomSegmentTrianglePairsAgreeWithDenseSampling)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  const auto rv = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  for (int trial = 0; trial < 25; ++trial) {
    const Vec3 p = rv(), q = rv(), a = rv(), b = rv(), c = rv();
    const int n = 60;
    const double sampled = sampledDistance(p, q, a, b, c, n);
    const GjkResult r = gjkDistance(SegmentShape(p, q), TriangleShape(a, b, c));
    const double spacing = std::max({(q - p).norm(), (b - a).norm(), (c - a).norm()}) / n;
    EXPECT_LE(r.distance, sampled + 1e-9) << "trial " << trial;
    EXPECT_GE(r.distance, sampled - 2.0 * spacing) << "trial " << trial;
    // The witnesses realise the distance.
    if (!r.intersecting) {
      EXPECT_NEAR((r.pointA - r.pointB).norm(), r.distance, 1e-7);
    }
  }
}

TEST(Gjk, WithinAgreesWithTheDistanceAwayFromTheThreshold)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  const auto rv = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const TriangleShape a(rv(), rv(), rv());
    const TriangleShape b(rv() + Vec3(6, 0, 0), rv() + Vec3(6, 0, 0), rv() + Vec3(6, 0, 0));
    const double d = gjkDistance(a, b).distance;
    for (const double margin : {0.0, 0.5, 2.0, 5.0}) {
      if (std::abs(d - margin) < 1e-6) continue;
      EXPECT_EQ(gjkWithin(a, b, margin), d <= margin) << "trial " << trial << " margin " << margin;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1500);
}

}  // namespace
}  // namespace spira
