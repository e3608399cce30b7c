// What decomposer.constant_distance refuses, and how it agrees with the iso-value strategy where both apply.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

#include "decomposer_constant_distance/tube_centre_line.h"
#include "spira/base/error.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "tube_plan_support.h"

namespace spira::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string writeFile(const std::string& name, const std::string& text)
{
  const auto path = std::filesystem::temp_directory_path() / ("spira_cd_" + name);
  std::ofstream(path) << text;
  return path.string();
}

void expectRefusal(const std::function<void()>& plan, const std::string& what, const std::string& hint)
{
  try {
    plan();
    FAIL() << "expected a refusal saying '" << what << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    EXPECT_NE(e.hint().find(hint), std::string::npos) << e.hint();
  }
}

// (rho, z) of a point of a part of revolution about z.
Eigen::Vector2d meridian(const Vec3& p)
{
  return {std::hypot(p.x(), p.y()), p.z()};
}

// On a part of revolution the layers at a constant distance are the iso-value layers: layer k lies k delta
// up each generatrix from the base. Each layer point is compared, in the meridian plane, with the iso-value
// decomposer's generatrix at that arc length.
void expectSameLayersAsIsovalue(const TriangleMesh& mesh, double delta)
{
  const PlanOutput cd = planTube(mesh, delta, 0.9 * delta, 1.1 * delta, "layers", "truncate", "", 120);
  const PlanOutput iso = planWith("decomposer.isovalue", mesh, delta, 0.9 * delta, 1.1 * delta, 120);
  const Polyline& g = iso.generatrices.lines.front();
  auto along = [&](double s) {
    for (size_t j = 1; j < g.size(); ++j) {
      const double l = (g[j] - g[j - 1]).norm();
      if (s <= l) return Eigen::Vector2d(meridian(g[j - 1] + (s / l) * (g[j] - g[j - 1])));
      s -= l;
    }
    return meridian(g.back());
  };
  double worst = 0.0;
  size_t compared = 0;
  for (const TrajectoryPoint& p : cd.spiral.trajectory.points) {
    const double s = (p.revolution + 1) * delta;
    worst = std::max(worst, (meridian(p.position) - along(s)).norm());
    ++compared;
  }
  EXPECT_GT(compared, 1000u);
  EXPECT_LT(worst, 0.01);
  std::printf("%zu layer points within %.4f mm of the iso-value generatrix\n", compared, worst);
}

TEST(ConstantDistanceInput, OnACylinderAndAConeTheLayersAreTheIsovalueOnes)
{
  expectSameLayersAsIsovalue(makeOpenCylinder(30.0, 40.0, 360, 20), 2.0);
  expectSameLayersAsIsovalue(makeOpenCone(35.0, 25.0, 40.0, 360, 20), 2.0);
}

TEST(ConstantDistanceInput, AGentleBendEndsOnItsEdgeWithModulatedLayers)
{
  const double bend = 200.0, angle = 0.3;  // outer wall 64.5 mm, inner 55.5 mm
  const TriangleMesh tube = makeBentTube(bend, 15.0, angle, segmentsForEdge(15.0, 2.0), 30);
  const PlanOutput plan = planTube(tube, 5.0, 4.5, 5.5, "layers", "modulate", "", 120);
  ASSERT_TRUE(plan.layers);
  EXPECT_TRUE(plan.feasible()) << plan.deposits.summary();
  EXPECT_EQ(plan.layers->arcStarts, plan.layers->layers);  // no piece cut off: one arc per layer
  EXPECT_GE(plan.layers->deltaMin, 4.5 - 0.025);
  EXPECT_LE(plan.layers->deltaMax, 5.5 + 0.025);
  // The last layer lies on the end face, the plane through the bend's axis at `angle`.
  double off = 0.0;
  for (const TrajectoryPoint& p : plan.spiral.trajectory.points)
    if (p.revolution == plan.layers->layers - 1) {
      const double rho = std::hypot(p.position.x() + bend, p.position.z());
      off = std::max(off, std::abs(std::atan2(p.position.z(), p.position.x() + bend) - angle) * rho);
    }
  EXPECT_LT(off, 0.01);
}

// A usual elbow (bend radius over 6 tube radii) folds no layer: feasible, and every bead at delta.
TEST(ConstantDistanceInput, AnElbowOfBendRadiusSixAndAHalfTubeRadiiIsBuildable)
{
  const double bend = 100.0, r = 15.0;
  const TriangleMesh tube =
      makeBentTube(bend, r, 0.5 * kPi, segmentsForEdge(r, 2.0), int(bend * 0.5 * kPi / 2.0));
  for (const char* output : {"layers", "spiral"}) {
    SCOPED_TRACE(output);
    const PlanOutput plan = planTube(tube, 2.0, 1.8, 2.2, output, "truncate", "", 180);
    ASSERT_TRUE(plan.layers);
    EXPECT_TRUE(plan.feasible()) << plan.deposits.summary();
    EXPECT_NEAR(plan.layers->deltaMin, 2.0, 1e-3);
    EXPECT_NEAR(plan.layers->deltaMax, 2.0, 1e-3);
    EXPECT_LT(plan.layers->maxKinkDeg, 90.0);
    // Iso-v stepping would lay ceil(outer wall / delta) layers.
    EXPECT_LT(plan.layers->layers, int(std::ceil((bend + r) * 0.5 * kPi / 2.0)));
    std::printf("elbow R %g r %g (%s): %d layers, kink %.1f deg, %d arcs, deposit check %.3f .. %.3f mm\n",
                bend, r, output, plan.layers->layers, plan.layers->maxKinkDeg, plan.layers->arcStarts,
                plan.deposits.heightMin, plan.deposits.heightMax);
  }
}

TEST(ConstantDistanceInput, TheCentreLineFromTheFieldFollowsTheBend)
{
  const TriangleMesh tube = quarterTorus();
  const PlanOutput plan = planTube(tube, 5.0, 4.5, 5.5, "layers", "truncate", "", 90);
  const MeshReport report = validateMesh(tube);
  ASSERT_GE(report.boundaryLoops.size(), 2u);
  const Polyline line =
      centreLineFromField(tube, plan.field, report.boundaryLoops.front(), report.boundaryLoops.back());
  double off = 0.0;
  for (const Vec3& p : line) off = std::max(off, std::hypot(std::hypot(p.x() + 50.0, p.z()) - 50.0, p.y()));
  // The harmonic field of a torus segment is linear in the bend angle: its levels are cross-sections.
  EXPECT_LT(off, 0.1);
  EXPECT_LT(line.front().norm(), 0.1);
  EXPECT_LT((line.back() - Vec3(-50.0, 0.0, 50.0)).norm(), 0.1);
}

TEST(ConstantDistanceInput, AUsersGuideGivesTheLayersOfTheAutomaticOne)
{
  std::string csv = "x,y,z\n";
  for (int k = 0; k <= 30; ++k) {
    const double t = 0.5 * kPi * k / 30;
    csv += std::to_string(50.0 * std::cos(t) - 50.0) + "," + std::to_string(0.0) + "," +
           std::to_string(50.0 * std::sin(t)) + "\n";
  }
  const TriangleMesh tube = quarterTorus();
  const PlanOutput given =
      planTube(tube, 5.0, 4.5, 5.5, "layers", "truncate", writeFile("arc.csv", csv), 180);
  const PlanOutput automatic = planTube(tube, 5.0, 4.5, 5.5, "layers", "truncate", "", 180);
  ASSERT_TRUE(given.layers && automatic.layers);
  EXPECT_EQ(given.layers->layers, automatic.layers->layers);
  EXPECT_EQ(given.deposits.flags.size(), automatic.deposits.flags.size());
  EXPECT_NEAR(given.layers->deltaMin, automatic.layers->deltaMin, 1e-4);
  EXPECT_NEAR(given.layers->maxKinkDeg, automatic.layers->maxKinkDeg, 2.0);
}

TEST(ConstantDistanceInput, RefusesWhatIsNotATubeOrCannotBeLaid)
{
  const TriangleMesh tube = quarterTorus();
  expectRefusal([&] { planTube(makeHemisphere(60.0, 96, 24), 2.0, 1.8, 2.2); }, "closed at the top",
                "--strategy");
  expectRefusal([&] { planTube(tube, 16.0, 15.0, 17.0, "layers", "truncate", "", 90); },
                "not smaller than the tube's radius", "lower --h below");
  expectRefusal(
      [&] {
        planTube(tube, 5.0, 4.5, 5.5, "layers", "truncate", writeFile("outside.csv", "0,40,0\n0,40,60\n"),
                 90);
      },
      "leaves the part", "--guide");
  expectRefusal(
      [&] {
        planTube(tube, 5.0, 4.5, 5.5, "layers", "truncate", writeFile("bad.csv", "x,y,z\n0,0,0\n0,zero,1\n"),
                 90);
      },
      "line 3", "x,y,z");
  expectRefusal(
      [&] { planTube(tube, 5.0, 4.5, 5.5, "layers", "truncate", writeFile("one.csv", "0,0,0\n"), 90); },
      "1 distinct guide point", "at least 2 points");
}

}  // namespace
}  // namespace spira::test
