// A feature added onto a pipe (004_bd0df31205c0c3c0.txt §2.2.3, validation V9): the source's quarter torus
// (bend radius 50, tube radius 15) on a cylinder of radius 32 about y. The base edge is the intersection
// curve, the layers start on it, and the first beads are measured down to the pipe.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "decomposer_constant_distance/tube_layers.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/base/segment_distance.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "tube_plan_support.h"

namespace spira::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double R = 50.0, r = 15.0, Rc = 32.0;

TriangleMesh feature()
{
  return makeTorusOnCylinder(R, r, Rc, 0.5 * kPi, segmentsForEdge(r, 1.0), 40);
}

// The pipe: x^2 + z^2 = Rc^2, 1 mm edges, 160 mm along y.
TriangleMesh pipe(double shiftZ = 0.0)
{
  const double length = 160.0;
  TriangleMesh m = makeOpenCylinder(Rc, length, segmentsForEdge(Rc, 1.0), 160);
  for (Vec3& v : m.vertices) v = Vec3(v.y(), v.z() - 0.5 * length, v.x() + shiftZ);
  return m;
}

TEST(ConstantDistanceSubstrate, TheFirstLayerOfATorusOnACylinderIsTheIntersectionCurve)
{
  const TriangleMesh part = feature();
  for (const Vec3& v : part.vertices) ASSERT_GE(std::hypot(v.x(), v.z()), Rc - 1e-9);
  const MeshReport report = validateMesh(part);
  ASSERT_EQ(report.boundaryLoops.size(), 2u);
  // The loop on the pipe is the one nearer the origin.
  const BoundaryLoop& base = report.boundaryLoops.front();
  const BoundaryLoop& top = report.boundaryLoops.back();
  EXPECT_LT(std::abs(std::hypot(part.vertices[size_t(base.vertices.front())].x(),
                                part.vertices[size_t(base.vertices.front())].z()) -
                     Rc),
            1e-9);
  EXPECT_GT(std::hypot(part.vertices[size_t(top.vertices.front())].x(),
                       part.vertices[size_t(top.vertices.front())].z()),
            Rc + 10.0);
  // The source's guide: the bend's centre arc, from inside the pipe.
  Polyline line;
  for (int k = 0; k <= 30; ++k) {
    const double t = 0.5 * kPi * k / 30;
    line.push_back(Vec3(R * std::cos(t) - R, 0.0, R * std::sin(t)));
  }
  TubeLayerSettings s;
  s.delta = 5.0, s.hMin = 4.5, s.hMax = 5.5, s.tolerance = 0.025, s.points = 360;
  NullProgress progress;
  const TubeLayers layers = layTubeLayers(part, line, 3.0 * r + 20.0, s, progress);
  // 004_bd0df31205c0c3c0.txt Eq. 2.17-2.19 at v = 0, 90 and 180 deg.
  for (const Vec3& expected :
       {Vec3(7.010, 0.0, 31.223), Vec3(-10.240, 15.0, 30.317), Vec3(-22.990, 0.0, 22.259)})
    EXPECT_LT(distanceToClosed(expected, layers.points[0]), 0.02) << expected.transpose();
  for (const Vec3& p : layers.points[0]) EXPECT_NEAR(std::hypot(p.x(), p.z()), Rc, 0.02);
}

TEST(ConstantDistanceSubstrate, APlanOnThePipeMeasuresItsFirstBeadsFromThePipe)
{
  const TriangleMesh part = feature();
  // Layers at the source's 5 mm; a spiral needs room for its start-up and termination ramps: 2 mm.
  for (const auto& [output, h] : {std::pair{"layers", 5.0}, std::pair{"spiral", 2.0}}) {
    SCOPED_TRACE(output);
    const PlanOutput plan = planTubeOn(part, pipe(), h, 0.9 * h, 1.1 * h, output, 180);
    ASSERT_TRUE(plan.layers);
    // Nothing under the first revolution is missing or too thin or too thick: it rests on the pipe.
    size_t firstRing = 0;
    for (const DepositFlag& f : plan.deposits.flags)
      if (plan.spiral.trajectory.points[f.point].revolution == 0) ++firstRing;
    EXPECT_EQ(firstRing, 0u) << plan.deposits.summary();
    double lo = 1e9, hi = 0.0;
    for (const TrajectoryPoint& p : plan.spiral.trajectory.points)
      if (p.revolution == 0) lo = std::min(lo, p.height), hi = std::max(hi, p.height);
    EXPECT_GE(lo, 0.9 * h - 0.005 * h);
    EXPECT_LE(hi, 1.1 * h + 0.005 * h);
    std::printf("torus on the pipe (%s): %d layers, first ring %.3f .. %.3f mm over the pipe, %s (%s)\n",
                output, plan.layers->layers, lo, hi, plan.feasible() ? "feasible" : "infeasible",
                plan.deposits.summary().c_str());
  }
}

TEST(ConstantDistanceSubstrate, APipeThePartDoesNotTouchIsRefused)
{
  try {
    planTubeOn(feature(), pipe(-4.0), 5.0, 4.5, 5.5, "layers", 90);
    FAIL() << "the feature lies 4 mm off the pipe";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not stand on the substrate mesh"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("mm from the substrate's surface"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spira::test
