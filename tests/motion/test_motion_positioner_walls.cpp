// Issue 14 item 6: vertical walls on the bundled FANUC positioner cell. The parts are planned by
// the real planner (isovalue spiral with its start-up and closing ramps, process channels) and
// solved as `spira-cli plan --cell` solves them; every check below is computed from the joints,
// the path and the cell file, not read from the motion report.
//
// Where a wall is vertical the build direction lies (almost) along the table's rotation axis, so
// the rotation is free; the planned build direction leans off it only by the spiral's climb and
// facet noise, and an exact flat-position solution then turns the table by up to 90 deg between
// neighbouring points. A rotation that keeps to its neighbours turns with the point: 360 / p deg
// per point for p points per revolution.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "builtin_plugins.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_report.h"
#include "spira/pipeline/plan_motion.h"
#include "spira/pipeline/sub_paths.h"
#include "spira/planning/planner.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
#include "support/test_support.h"

namespace spira {
namespace {

const RobotCell& fanucCell()
{
  static const RobotCell cell(
      readCellFile(test::sourceDir() / "resources" / "cells" / "fanuc_m20ia_positioner.cell"));
  return cell;
}

Trajectory planMesh(const TriangleMesh& mesh, int pointsPerRevolution)
{
  const MeshReport report = validateMesh(mesh);
  PlanRequest request(mesh, report);
  request.params["decomposer.isovalue"].set("points_per_rev", std::int64_t{pointsPerRevolution});
  NullProgress progress;
  const PlanOutput plan = planPart(builtinRegistry(), request, progress);
  EXPECT_TRUE(plan.feasible());
  return plan.spiral.trajectory;
}

// A repeatable pseudo-random number in [-0.5, 0.5) for vertex (i, k).
double jitter(int i, int k, double salt)
{
  const double v = std::sin(12.9898 * i + 78.233 * k + salt) * 43758.5453;
  return v - std::floor(v) - 0.5;
}

// A surface of revolution through the profile points (r, z), meshed like a CAD export rather than
// in aligned rings: every vertex slides along the surface by up to 0.3 of a segment around the
// axis, and by up to 0.6 mm up or down where the profile is vertical. The generatrices then cross
// the triangles obliquely, and the planned build directions of a vertical wall lean off the axis
// by facet noise. A last profile point with r = 0 closes the top with one vertex on the axis.
TriangleMesh cadLikeRevolved(const std::vector<Eigen::Vector2d>& profile, int segments)
{
  TriangleMesh mesh;
  const bool closed = profile.back().x() == 0.0;
  const int rings = static_cast<int>(profile.size()) - (closed ? 1 : 0);
  for (int i = 0; i < rings; ++i) {
    const bool vertical = i > 0 && i + 1 < rings && profile[i - 1].x() == profile[i].x() &&
                          profile[i + 1].x() == profile[i].x();
    for (int k = 0; k < segments; ++k) {
      const double a = 2.0 * kPi * (k + 0.6 * jitter(i, k, 0.0)) / segments;
      const double z = profile[i].y() + (vertical ? 1.2 * jitter(i, k, 1.0) : 0.0);
      mesh.vertices.emplace_back(profile[i].x() * std::cos(a), profile[i].x() * std::sin(a), z);
    }
  }
  for (int i = 0; i + 1 < rings; ++i)
    for (int k = 0; k < segments; ++k) {
      const int a = i * segments + k, b = i * segments + (k + 1) % segments;
      mesh.faces.push_back({a, b, b + segments});
      mesh.faces.push_back({a, b + segments, a + segments});
    }
  if (closed) {
    const int pole = static_cast<int>(mesh.vertices.size());
    mesh.vertices.emplace_back(0.0, 0.0, profile.back().y());
    const int last = (rings - 1) * segments;
    for (int k = 0; k < segments; ++k) mesh.faces.push_back({last + k, last + (k + 1) % segments, pole});
  }
  return mesh;
}

std::vector<Eigen::Vector2d> cylinderProfile(double r, double height)
{
  std::vector<Eigen::Vector2d> profile;
  for (double z = 0.0; z <= height + 1e-9; z += 2.0) profile.emplace_back(r, z);
  return profile;
}

// A bottle: a vertical wall of radius r and `height`, closed by a hemisphere whose pole is on the axis.
std::vector<Eigen::Vector2d> bottleProfile(double r, double height)
{
  std::vector<Eigen::Vector2d> profile = cylinderProfile(r, height);
  const int steps = static_cast<int>(std::ceil(0.5 * kPi * r / 2.0));
  for (int k = 1; k < steps; ++k) {
    const double a = 0.5 * kPi * k / steps;
    profile.emplace_back(r * std::cos(a), height + r * std::sin(a));
  }
  profile.emplace_back(0.0, height + r);
  return profile;
}

// A vase: a vertical foot, a belly leaning out by up to 25 deg and back in, a vertical neck
// `neck` mm long and a flared lip.
std::vector<Eigen::Vector2d> vaseProfile(double neck)
{
  std::vector<Eigen::Vector2d> profile;
  const auto add = [&profile](double r, double z) { profile.emplace_back(r, z); };
  for (double z = 0.0; z < 30.0; z += 2.0) add(40.0, z);  // foot
  for (double z = 30.0; z < 110.0; z += 2.0)              // belly: r = 40 + 12 sin^2
    add(40.0 + 12.0 * std::pow(std::sin(kPi * (z - 30.0) / 80.0), 2), z);
  for (double z = 110.0; z < 110.0 + neck; z += 2.0) add(40.0, z);   // neck
  for (double z = 110.0 + neck; z <= 130.0 + neck + 1e-9; z += 2.0)  // lip, out to r = 44
    add(40.0 + 4.0 * std::pow((z - 110.0 - neck) / 20.0, 2), z);
  return profile;
}

// The largest turn of the table between neighbouring points, 1.4 mm apart, on the parts below.
// It turns with the part, 2 deg per point, but where a wall starts to lean just past the 2 deg the
// positioner may leave (MotionParams::buildTiltToleranceDeg), the rotation must also follow the
// azimuth of the lean, which facet noise moves by a few degrees from point to point (an exact
// flat position follows it everywhere, and jumps by up to 90 deg where the lean is noise). 10 deg
// is still far below the 58 deg the rotary axis turns at its 120 deg/s in the 0.48 s between
// points at 2.9 mm/s.
constexpr double kTransitionStepDeg = 10.0;

// What the joints of a solved path ask of each axis.
struct AxisDemand {
  double maxSpeedRatio = 0.0;  // largest |dA/dt| / the cell's max speed of any axis
  std::string axis;            // where it is
  size_t point = 0;
  double maxStepE2 = 0.0;  // largest |dE2| between consecutive points, deg
  double minE2 = 1e300, maxE2 = -1e300;
  double maxLeanDeg = 0.0;  // largest angle between a turned build direction and the vertical
};

AxisDemand demand(const RobotCell& cell, const Trajectory& path, const JointTrajectory& joints)
{
  const CellRecord& rec = cell.record();
  const JointPathSetup setup = cell.setup();
  AxisDemand d;
  for (size_t i = 0; i < joints.size(); ++i) {
    const JointPoint& p = joints.points[i];
    d.minE2 = std::min(d.minE2, p.externalDeg[1]);
    d.maxE2 = std::max(d.maxE2, p.externalDeg[1]);
    const Eigen::Vector2d e(degToRad(p.externalDeg[0]), degToRad(p.externalDeg[1]));
    const Vec3 up = setup.positioner->forward(e).linear() * setup.tablePart.linear() * path.points[i].build;
    d.maxLeanDeg = std::max(d.maxLeanDeg, radToDeg(std::acos(std::clamp(up.normalized().z(), -1.0, 1.0))));
    if (i == 0) continue;
    const JointPoint& q = joints.points[i - 1];
    d.maxStepE2 = std::max(d.maxStepE2, std::abs(p.externalDeg[1] - q.externalDeg[1]));
    const double dt =
        (path.points[i].position - path.points[i - 1].position).norm() / path.points[i].travelSpeed;
    const auto check = [&](double move, const CellAxis& axis, const std::string& name) {
      const double ratio = std::abs(move) / dt / axis.maxSpeedDegPerS;
      if (ratio > d.maxSpeedRatio) {
        d.maxSpeedRatio = ratio;
        d.axis = name;
        d.point = i;
      }
    };
    for (size_t j = 0; j < 6; ++j)
      check(p.robotDeg[j] - q.robotDeg[j], rec.robotAxes[j], "J" + std::to_string(j + 1));
    for (size_t k = 0; k < 2; ++k)
      check(p.externalDeg[k] - q.externalDeg[k], rec.positionerAxes[k], "E" + std::to_string(k + 1));
  }
  return d;
}

MotionResult solveOnCell(const Trajectory& path)
{
  NullProgress progress;
  return solveSubPaths(fanucCell(), path, motionParamsFor(fanucCell(), MotionSettings{}), progress);
}

TEST(PositionerWalls, CylinderTurnsTheTableWithThePoint)
{
  // R 50 mm, 40 mm tall: 20 revolutions of 2 mm, 360 points each, 0.87 mm apart.
  const int perRevolution = 360;
  const Trajectory path = planMesh(cadLikeRevolved(cylinderProfile(50.0, 40.0), 157), perRevolution);
  ASSERT_GT(path.size(), 7000u);
  const MotionResult r = solveOnCell(path);
  for (const JointPoint& p : r.joints.points) ASSERT_TRUE(p.reachable);
  const AxisDemand d = demand(fanucCell(), path, r.joints);
  // The table turns with the part, 1 deg per point; 10 % more covers the ramps' and the mesh's
  // uneven spacing of the points.
  EXPECT_LT(d.maxStepE2, 1.1 * 360.0 / perRevolution);
  EXPECT_LE(d.maxSpeedRatio, 1.0) << d.axis << " at point " << d.point;
  // ... and the deposit stays within 2 deg of flat (MotionParams::buildTiltToleranceDeg).
  EXPECT_LE(d.maxLeanDeg, 2.0 + 1e-6);
}

TEST(PositionerWalls, BottleTurnsTheTableWithThePointUpToItsClosurePoint)
{
  // R 40 mm: 30 mm of wall, then a dome whose build directions lean over towards the horizontal
  // at the top, closing on a point on the table's axis, whose azimuth about the axis is noise.
  const int perRevolution = 180;
  const Trajectory path = planMesh(cadLikeRevolved(bottleProfile(40.0, 30.0), 126), perRevolution);
  const MotionResult r = solveOnCell(path);
  for (const JointPoint& p : r.joints.points) ASSERT_TRUE(p.reachable);
  const AxisDemand d = demand(fanucCell(), path, r.joints);
  EXPECT_LE(d.maxSpeedRatio, 1.0) << d.axis << " at point " << d.point;
  EXPECT_LT(d.maxStepE2, kTransitionStepDeg);
  EXPECT_LE(d.maxLeanDeg, 2.0 + 1e-6);
  // Over the dome the table turns with the point, 2 deg per point; no turn of the table moves the
  // closure point, so it holds still into it.
  const size_t n = path.size();
  ASSERT_LT(path.points[n - 1].position.head<2>().norm(), 0.01);
  EXPECT_NEAR(std::abs(r.joints.points[n - 2].externalDeg[1] - r.joints.points[n - 3].externalDeg[1]),
              360.0 / perRevolution, 0.1);
  EXPECT_LT(std::abs(r.joints.points[n - 1].externalDeg[1] - r.joints.points[n - 2].externalDeg[1]), 0.1);
}

TEST(PositionerWalls, VaseKeepsEveryAxisWithinItsSpeedLimitAndTheRotaryAxisInItsRange)
{
  // 130 mm of vertical neck: a part 260 mm tall, 132 revolutions of 2 mm. The table turns once
  // per revolution with the part, about 47,500 deg: more than the rotary axis's +-36,000 deg hold
  // from a start near 0, well within its 72,000 deg of travel when wound from the other end.
  const int perRevolution = 180;
  const Trajectory path = planMesh(cadLikeRevolved(vaseProfile(130.0), 126), perRevolution);
  const MotionResult r = solveOnCell(path);
  size_t unreachable = 0;
  for (const JointPoint& p : r.joints.points) unreachable += !p.reachable;
  EXPECT_EQ(unreachable, 0u);
  const AxisDemand d = demand(fanucCell(), path, r.joints);
  EXPECT_LE(d.maxSpeedRatio, 1.0) << d.axis << " at point " << d.point;
  EXPECT_LT(d.maxStepE2, kTransitionStepDeg);
  EXPECT_LE(d.maxLeanDeg, 2.0 + 1e-6);
  const CellAxis& e2 = fanucCell().record().positionerAxes[1];
  EXPECT_GT(d.maxE2 - d.minE2, 36000.0);
  EXPECT_GE(d.minE2, e2.minDeg);
  EXPECT_LE(d.maxE2, e2.maxDeg);
}

}  // namespace
}  // namespace spira
