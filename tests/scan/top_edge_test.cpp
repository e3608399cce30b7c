// The top edge measured through the point grid gives exactly what visiting every scan point gave:
// the same samples and the same medians, on simulated walls with stray points near and far.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "builtin_plugins.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/planner.h"
#include "spira/scan/built_wall.h"
#include "spira/scan/point_grid.h"

namespace spira {
namespace {

constexpr double kBead = 5.2;

Trajectory planOf(const TriangleMesh& mesh)
{
  const MeshReport report = validateMesh(mesh);
  NullProgress progress;
  return planPart(builtinRegistry(), PlanRequest(mesh, report), progress).spiral.trajectory;
}

// measureTopEdge's samples and median per edge point as it was written first: every scan point tried.
void bruteForce(const Trajectory& plan, const MeasuredEdge& edge, const PointCloud& scan, double beadWidth,
                std::vector<size_t>& samples, std::vector<double>& shortfall)
{
  const double r = 0.5 * beadWidth;
  samples.assign(edge.points.size(), 0);
  shortfall.assign(edge.points.size(), NAN);
  for (size_t e = 0; e < edge.points.size(); ++e) {
    const size_t i = edge.points[e];
    const TrajectoryPoint& p = plan.points[i];
    const Vec3 b = p.build.normalized();
    const Vec3 n = (p.normal - p.normal.dot(b) * b).normalized();
    const Vec3 t = b.cross(n);
    const double step =
        0.5 * std::max(i + 1 < plan.size() ? (plan.points[i + 1].position - p.position).norm() : 0.0,
                       i > 0 ? (p.position - plan.points[i - 1].position).norm() : 0.0);
    std::vector<double> tops;
    for (const Vec3& q : scan.points) {
      const Vec3 d = q - p.position;
      const double across = d.dot(n);
      if (std::abs(across) > 0.5 * r || std::abs(d.dot(t)) > std::max(step, 0.25 * r)) continue;
      tops.push_back(d.dot(b) + r - std::sqrt(r * r - across * across));
    }
    if (tops.empty()) continue;
    std::sort(tops.begin(), tops.end());
    const double high = tops[tops.size() - 1 - tops.size() / 10];
    const auto from = std::lower_bound(tops.begin(), tops.end(), high - 0.5 * r);
    samples[e] = size_t(tops.end() - from);
    shortfall[e] = -*(from + (tops.end() - from) / 2);
  }
}

void expectSameAsBruteForce(const Trajectory& plan, size_t at, const PointCloud& scan, const char* name)
{
  const MeasuredEdge edge = measureTopEdge(plan, at, scan, kBead);
  std::vector<size_t> samples;
  std::vector<double> shortfall;
  bruteForce(plan, edge, scan, kBead, samples, shortfall);
  size_t measured = 0, total = 0;
  for (size_t e = 0; e < edge.points.size(); ++e) {
    ASSERT_EQ(edge.samples[e], samples[e]) << name << " edge point " << e;
    if (samples[e] == 0) continue;
    ++measured, total += samples[e];
    // Bit for bit: the same samples sorted give the same median.
    EXPECT_EQ(edge.shortfall[e], shortfall[e]) << name << " edge point " << e;
  }
  std::printf("%s: %zu scan points, %zu of %zu edge points measured from %zu samples, as by brute force\n",
              name, scan.size(), measured, edge.points.size(), total);
  EXPECT_GT(measured, edge.points.size() / 2) << name;
}

// Stray returns: a cloud of points over the wall's box and a few far off (which enlarge the cells).
void addStrays(PointCloud& scan, size_t count, bool far)
{
  const BoundingBox box = boundsOf(scan);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (size_t k = 0; k < count; ++k)
    scan.points.push_back(box.min + box.size().cwiseProduct(Vec3(unit(random), unit(random), unit(random))));
  if (far) {
    scan.points.emplace_back(5000.0, -3000.0, 200.0);
    scan.points.emplace_back(-2000.0, 0.0, -900.0);
  }
}

TEST(TopEdge, TheGridFindsExactlyWhatEveryPointGave)
{
  const Trajectory dome = planOf(makeHemisphere(60.0, 96, 48));
  DepositErrors sag;
  sag.kind = DepositErrors::Kind::Sag;
  sag.relative = -0.08;
  sag.until = 0.3;
  const size_t half = dome.size() / 2;
  PointCloud scan = scanOfBuild(dome, half, builtShortfall(dome, half, sag), kBead, 3, 10.4, 0.05, 3);
  addStrays(scan, 2000, false);
  expectSameAsBruteForce(dome, half, scan, "dome at half, 8 % sag, strays");
  addStrays(scan, 10, true);
  expectSameAsBruteForce(dome, half, scan, "the same with points metres away");
  // Near the closure the generatrices lean in: the build direction is far from z.
  const size_t late = dome.size() * 9 / 10;
  DepositErrors uniform;
  uniform.relative = -0.08;
  expectSameAsBruteForce(
      dome, late, scanOfBuild(dome, late, builtShortfall(dome, late, uniform), kBead, 3, 10.4, 0.05, 4),
      "dome at 90 %, 8 % under");

  const Trajectory cylinder = planOf(makeOpenCylinder(50.0, 100.0, 120, 50));
  const size_t third = cylinder.size() / 3;
  // Only the crowns, scanned down a whole revolution: parts of the wall far below each point.
  expectSameAsBruteForce(
      cylinder, third,
      scanOfBuild(cylinder, third, builtShortfall(cylinder, third, uniform), kBead, 6, 12.0, 0.0),
      "cylinder at a third, no noise");
}

// Every point within the radius of the line comes back exactly once, whatever the line's direction,
// for random points, with lines along the axes (zero components) and skewed ones.
TEST(PointGrid, ALineQueryHoldsEveryPointNearItOnce)
{
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int k = 0; k < 20000; ++k)
    points.emplace_back(40.0 * unit(random), 25.0 * unit(random), 10.0 * unit(random));
  points.emplace_back(900.0, 0.0, 0.0);  // one far point: larger cells
  for (double cell : {0.5, 2.6, 30.0}) {
    const PointGrid grid(points, cell);
    std::vector<Vec3> axes = {Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitZ()};
    for (int k = 0; k < 20; ++k) axes.push_back(Vec3(unit(random), unit(random), unit(random)).normalized());
    for (const Vec3& axis : axes) {
      const Vec3 origin(30.0 * unit(random), 20.0 * unit(random), 8.0 * unit(random));
      const double radius = 1.5 + 0.5 * unit(random);
      std::vector<std::uint32_t> near;
      grid.nearLine(origin, axis, radius, near);
      std::vector<std::uint32_t> sorted = near;
      std::sort(sorted.begin(), sorted.end());
      ASSERT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a point twice";
      size_t within = 0;
      for (size_t i = 0; i < points.size(); ++i) {
        const Vec3 d = points[i] - origin;
        if ((d - d.dot(axis) * axis).norm() > radius) continue;
        ++within;
        ASSERT_TRUE(std::binary_search(sorted.begin(), sorted.end(), std::uint32_t(i)))
            << "point " << i << " at " << (d - d.dot(axis) * axis).norm() << " mm of the line, cell " << cell;
      }
      EXPECT_GT(within, 0u);
    }
  }
  std::vector<std::uint32_t> none;
  PointGrid(points, 1.0).nearLine(Vec3(0.0, 500.0, 0.0), Vec3::UnitX(), 2.0, none);
  EXPECT_TRUE(none.empty());
  PointGrid({}, 1.0).nearLine(Vec3::Zero(), Vec3::UnitZ(), 2.0, none);
  EXPECT_TRUE(none.empty());
}

}  // namespace
}  // namespace spira
