// The shell mesh cut from a trajectory: it covers the deposit without gaps or overlaps (its area is
// the wall's), numbers nodes in deposition order, times the torch from the TS channel, and refuses
// trajectories it cannot heat.
#include <gtest/gtest.h>

#include <cmath>

#include "spira/base/error.h"
#include "spira/thermal/thermal_mesh.h"
#include "thermal/thermal_cases.h"

namespace spira {
namespace {

double meshArea(const ThermalMesh& m)
{
  double a = 0.0;
  for (const auto& t : m.triangles)
    a += test::triangleArea(m.nodes[size_t(t[0])], m.nodes[size_t(t[1])], m.nodes[size_t(t[2])]);
  return a;
}

// Flat revolutions of a polygon from the substrate (z = 0) to the top revolution: the shell is the
// prism, whatever k and f.
TEST(ThermalMesh, CylinderShellHasThePrismArea)
{
  const int n = 60;
  const Trajectory t = test::cylinderWall(20.0, 6, n, 2.0, 6.0);
  const double prism = n * 2.0 * 20.0 * std::sin(3.14159265358979323846 / n) * 12.0;
  for (int k : {1, 2, 3})
    for (int f : {1, 2}) {
      ThermalMeshSettings s;
      s.subSegments = k;
      s.divisions = f;
      const ThermalMesh m = buildThermalMesh(t, s);
      EXPECT_NEAR(meshArea(m), prism, 1e-9 * prism) << "k " << k << " f " << f;
      EXPECT_EQ(m.heatNode.size(), (t.size() - 1) * size_t(k) + 1);
      EXPECT_EQ(m.substrateNodes.size(), size_t(n * k + 1));
      for (int v : m.substrateNodes) EXPECT_EQ(m.nodes[size_t(v)].z(), 0.0);
    }
}

TEST(ThermalMesh, PointsLieOnTheirNodesAndOverTheLayerBelow)
{
  const Trajectory t = test::cylinderWall(20.0, 4, 48, 2.0, 6.0);
  ThermalMeshSettings s;
  s.subSegments = 2;
  s.divisions = 2;
  const ThermalMesh m = buildThermalMesh(t, s);
  for (size_t i = 0; i < t.size(); ++i) {
    const Vec3& p = t.points[i].position;
    EXPECT_LT((m.nodes[size_t(m.heatNode[size_t(m.pointHeatIndex[i])])] - p).norm(), 1e-12);
    const Vec3& below = m.nodes[size_t(m.pointBelowNode[i])];
    EXPECT_NEAR(below.z(), p.z() - 2.0, 1e-12) << i;
    EXPECT_LT((below - p).head<2>().norm(), 1e-9) << i;
  }
}

// Revolutions with different point counts are zipped together; the closure point is a fan.
TEST(ThermalMesh, UnequalRevolutionsAndAClosurePointLeaveNoGap)
{
  Trajectory t;
  const int counts[] = {80, 64, 100, 72};
  for (int r = 0; r < 4; ++r)
    for (int g = 0; g < counts[r]; ++g) {
      const double a = 2.0 * 3.14159265358979323846 * g / counts[r];
      TrajectoryPoint p;
      p.position = Vec3(20.0 * std::cos(a), 20.0 * std::sin(a), 2.0 * (r + 1));
      p.revolution = r;
      p.generatrix = g;
      p.travelSpeed = 5.0;
      t.points.push_back(p);
    }
  const double area = meshArea(buildThermalMesh(t, {}));
  EXPECT_NEAR(area, 2.0 * 3.14159265358979323846 * 20.0 * 8.0, 0.01 * area);

  const ThermalMesh dome = buildThermalMesh(test::hemisphereDome(30.0, 2.0, 120, 6.0), {});
  const double hemisphere = 2.0 * 3.14159265358979323846 * 30.0 * 30.0;
  // The polygonal rings and the first ring's drop to the substrate plane: within 2 % of the sphere's.
  EXPECT_NEAR(meshArea(dome), hemisphere, 0.02 * hemisphere);
  int atApex = 0;
  const int apex = dome.heatNode.back();
  for (const auto& tri : dome.triangles) atApex += tri[0] == apex || tri[1] == apex || tri[2] == apex;
  EXPECT_GE(atApex, 120);
}

TEST(ThermalMesh, TorchTimesComeFromTheTravelSpeedAndNodesFollowDeposition)
{
  Trajectory t = test::cylinderWall(20.0, 3, 40, 2.0, 4.0);
  for (size_t i = 40; i < t.size(); ++i) t.points[i].travelSpeed = 8.0;
  ThermalMeshSettings s;
  s.subSegments = 2;
  const ThermalMesh m = buildThermalMesh(t, s);
  double time = 0.0;
  for (size_t i = 1; i < t.size(); ++i) {
    const double v =
        t.points[i - 1].travelSpeed;  // each segment at its first point's speed, as the build time
    time += (t.points[i].position - t.points[i - 1].position).norm() / v;
    EXPECT_NEAR(m.heatTime[size_t(m.pointHeatIndex[i])], time, 1e-9 * time);
  }
  // A node's index never comes before one deposited earlier.
  std::vector<double> birth(m.nodeCount(), 1e300);
  for (size_t e = 0; e < m.elementCount(); ++e)
    for (int v : m.triangles[e]) birth[size_t(v)] = std::min(birth[size_t(v)], m.elementBirth[e]);
  for (size_t v = 1; v < m.nodeCount(); ++v) EXPECT_LE(birth[v - 1], birth[v]);
}

// Two paths: each rests on the substrate, the move between them carries no heat.
TEST(ThermalMesh, PathsAreLaidOneAfterTheOtherWithAColdMoveBetween)
{
  Trajectory t = test::cylinderWall(15.0, 3, 40, 2.0, 6.0);
  Trajectory second = test::cylinderWall(15.0, 3, 40, 2.0, 6.0);
  for (TrajectoryPoint& p : second.points) {
    p.position.x() += 50.0;
    p.path = 1;
  }
  t.points.insert(t.points.end(), second.points.begin(), second.points.end());
  const ThermalMesh m = buildThermalMesh(t, {});
  EXPECT_EQ(m.substrateNodes.size(), size_t(2 * 41));
  int cold = 0;
  for (char on : m.heatArcOn) cold += !on;
  EXPECT_EQ(cold, 1);
  EXPECT_FALSE(m.heatArcOn[size_t(m.pointHeatIndex[120] - 1)]);
}

// A branch that starts above the substrate rests on the nearest nodes of the paths laid before it.
TEST(ThermalMesh, ABranchRestsOnTheEarlierPaths)
{
  Trajectory t = test::cylinderWall(15.0, 3, 40, 2.0, 6.0);
  Trajectory branch = test::cylinderWall(15.0, 2, 40, 2.0, 6.0);
  for (TrajectoryPoint& p : branch.points) {
    p.position.z() += 12.0;
    p.path = 1;
  }
  t.points.insert(t.points.end(), branch.points.begin(), branch.points.end());
  const ThermalMesh m = buildThermalMesh(t, {});
  EXPECT_EQ(m.substrateNodes.size(), size_t(41));
  for (size_t i = 120; i < 160; ++i) {
    const Vec3& below = m.nodes[size_t(m.pointBelowNode[i])];
    EXPECT_NEAR(below.z(), 6.0, 1e-9) << i;
    EXPECT_LT((below - t.points[i].position).head<2>().norm(), 1e-9) << i;
  }
}

TEST(ThermalMesh, RefusesWhatItCannotHeat)
{
  EXPECT_THROW(buildThermalMesh({}, {}), InputError);
  Trajectory t = test::cylinderWall(20.0, 2, 20, 2.0, 6.0);
  ThermalMeshSettings bad;
  bad.thickness = 0.0;
  EXPECT_THROW(buildThermalMesh(t, bad), InputError);
  bad = {};
  bad.divisions = 0;
  EXPECT_THROW(buildThermalMesh(t, bad), InputError);
  t.points[7].travelSpeed = 0.0;
  try {
    buildThermalMesh(t, {});
    ADD_FAILURE() << "a point without travel speed was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("point 7"), std::string::npos) << e.what();
    EXPECT_NE(e.hint().find("process"), std::string::npos);
  }
}

}  // namespace
}  // namespace spira
