#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "spira/collision/capsule_bvh.h"
#include "spira/collision/gjk.h"
#include "spira/collision/torch_solid.h"
#include "spira/collision/triangle_bvh.h"
#include "spira/path/tool_frame.h"

namespace spira {
namespace {

struct Rng {
  std::mt19937 gen;
  explicit Rng(unsigned seed) : gen(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(gen); }
  Vec3 point(double a, double b) { return Vec3(uniform(a, b), uniform(a, b), uniform(a, b)); }
  Vec3 direction()
  {
    Vec3 d;
    do d = point(-1, 1);
    while (d.norm() < 0.1 || d.norm() > 1.0);
    return d.normalized();
  }
};

TriangleMesh triangleSoup(Rng& rng, int count)
{
  TriangleMesh mesh;
  for (int f = 0; f < count; ++f) {
    const Vec3 c = rng.point(0, 300);
    const int base = static_cast<int>(mesh.vertices.size());
    for (int k = 0; k < 3; ++k) mesh.vertices.push_back(c + rng.point(-8, 8));
    mesh.faces.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

TorchSolid randomTorch(Rng& rng)
{
  TrajectoryPoint p;
  p.position = rng.point(-150, 450);
  p.build = rng.direction();
  p.tangent = p.build.unitOrthogonal();
  p.normal = p.tangent.cross(p.build);
  return TorchSolid(TorchParams(), toolFrame(p));
}

TEST(Bvh, TreeHoldsEveryPrimitiveOnceInsideItsNodeBoxes)
{
  Rng rng(1);
  const TriangleMesh soup = triangleSoup(rng, 1000);
  const TriangleBvh bvh(soup);
  std::vector<int> seen(soup.faceCount(), 0);
  for (const uint32_t p : bvh.tree().order()) ++seen[p];
  for (const int s : seen) EXPECT_EQ(s, 1);
  const auto& nodes = bvh.tree().nodes();
  for (const auto& node : nodes) {
    if (!node.leaf()) continue;
    for (uint32_t k = node.first; k < node.first + node.count; ++k) {
      const BoundingBox box = bvh.triangle(bvh.tree().order()[k]).bounds();
      EXPECT_TRUE((box.min.array() >= node.box.min.array()).all() &&
                  (box.max.array() <= node.box.max.array()).all());
    }
  }
}

TEST(Bvh, TriangleQueriesEqualBruteForce)
{
  Rng rng(2);
  const TriangleMesh soup = triangleSoup(rng, 3000);
  const TriangleBvh bvh(soup);
  int hits = 0;
  for (int q = 0; q < 60; ++q) {
    const TorchSolid torch = randomTorch(rng);
    const double margin = rng.uniform(0.0, 6.0);
    std::vector<size_t> brute;
    double bruteNearest = std::numeric_limits<double>::infinity();
    size_t bruteFace = 0;
    for (size_t f = 0; f < soup.faceCount(); ++f) {
      const TriangleShape t = bvh.triangle(f);
      if (gjkWithin(torch, t, margin)) brute.push_back(f);
      const double d = gjkDistance(torch, t).distance;
      if (d < bruteNearest) {
        bruteNearest = d;
        bruteFace = f;
      }
    }
    hits += !brute.empty();
    EXPECT_EQ(bvh.intersects(torch, margin), !brute.empty()) << "query " << q;
    EXPECT_EQ(bvh.within(torch, margin), brute) << "query " << q;
    const NearestHit hit = bvh.nearest(torch);
    ASSERT_TRUE(hit.found());
    EXPECT_NEAR(hit.distance, bruteNearest, 1e-6) << "query " << q;
    if (hit.primitive != bruteFace) {
      EXPECT_NEAR(gjkDistance(torch, bvh.triangle(hit.primitive)).distance, bruteNearest, 1e-6);
    }
    // A search radius below the nearest distance finds nothing.
    EXPECT_FALSE(bvh.nearest(torch, 0.5 * bruteNearest).found());
  }
  // Both outcomes were exercised.
  EXPECT_GT(hits, 5);
  EXPECT_LT(hits, 55);
}

TEST(Bvh, CapsuleQueriesWithKeyCutoffsEqualBruteForce)
{
  Rng rng(3);
  std::vector<Capsule> caps;
  std::vector<uint32_t> keys;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 a = rng.point(0, 300);
    caps.push_back({a, a + rng.point(-6, 6), rng.uniform(0.5, 3.0)});
    keys.push_back(static_cast<uint32_t>(3 * i + 1));  // sparse keys, as arc-off segments leave gaps
  }
  const CapsuleBvh bvh(caps, keys);
  for (int q = 0; q < 60; ++q) {
    const TorchSolid torch = randomTorch(rng);
    const double margin = rng.uniform(0.0, 4.0);
    const uint32_t keyEnd = static_cast<uint32_t>(rng.uniform(0, 12000));
    std::vector<size_t> brute;
    double bruteNearest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < caps.size(); ++i) {
      if (keys[i] >= keyEnd) continue;
      const SegmentShape s(caps[i].a, caps[i].b);
      if (gjkWithin(torch, s, margin + caps[i].radius)) brute.push_back(i);
      bruteNearest = std::min(bruteNearest, std::max(0.0, gjkDistance(torch, s).distance - caps[i].radius));
    }
    EXPECT_EQ(bvh.intersects(torch, margin, keyEnd), !brute.empty()) << "query " << q;
    EXPECT_EQ(bvh.within(torch, margin, keyEnd), brute) << "query " << q;
    // A hint (tried first) never changes the answer: none, a random capsule (often hidden by
    // keyEnd or far away), or one that is hit; a hit leaves the hint on a capsule that is hit.
    for (const uint32_t start : {CapsuleBvh::kAll, static_cast<uint32_t>(rng.uniform(0, 4000)),
                                 brute.empty() ? CapsuleBvh::kAll : static_cast<uint32_t>(brute.back())}) {
      uint32_t hint = start;
      ASSERT_EQ(bvh.intersects(torch, margin, keyEnd, &hint), !brute.empty()) << "query " << q;
      if (!brute.empty()) {
        EXPECT_TRUE(std::binary_search(brute.begin(), brute.end(), size_t(hint))) << "query " << q;
      }
    }
    const NearestHit hit = bvh.nearest(torch, keyEnd);
    EXPECT_EQ(hit.found(), std::isfinite(bruteNearest));
    if (hit.found()) {
      EXPECT_NEAR(hit.distance, bruteNearest, 1e-6) << "query " << q;
      EXPECT_LT(keys[hit.primitive], keyEnd);
    }
  }
}

}  // namespace
}  // namespace spira
