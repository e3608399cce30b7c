// What the spiral builder refuses (InputError with a hint), and what it repairs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "analytic_generatrices.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/path/feasibility.h"
#include "spira/path/spiral_builder.h"

using namespace spira;

namespace {

SpiralSettings mm1()
{
  SpiralSettings s;
  s.h = 1.0;
  s.hMin = 0.9;
  s.hMax = 1.1;
  return s;
}

// The InputError message of building `g` with `s`, or "" when nothing is thrown.
std::string inputError(const Generatrices& g, const SpiralSettings& s)
{
  NullProgress progress;
  try {
    buildSpiral(g, s, progress);
  } catch (const InputError& e) {
    EXPECT_FALSE(e.hint().empty()) << e.what();
    return e.what();
  }
  return {};
}

bool mentions(const std::string& text, const std::string& word)
{
  return text.find(word) != std::string::npos;
}

}  // namespace

TEST(SpiralInput, RejectsBadSettings)
{
  const Generatrices g = test::cylinder(50, 100, 36, 5);
  SpiralSettings s = mm1();
  s.hMin = 1.2;
  EXPECT_TRUE(mentions(inputError(g, s), "h_min must be smaller than h_max"));
  s = mm1();
  s.h = 1.3;
  EXPECT_TRUE(mentions(inputError(g, s), "outside the modulation window"));
  s = mm1();
  s.hMin = -0.1;
  EXPECT_TRUE(mentions(inputError(g, s), "must be positive"));
  s = mm1();
  s.heightTolerance = -0.1;
  EXPECT_TRUE(mentions(inputError(g, s), "tolerance"));
  s = mm1();
  s.minRevolutionLength = -1.0;
  EXPECT_TRUE(mentions(inputError(g, s), "minimum revolution length"));
}

TEST(SpiralInput, RejectsBadGeneratrices)
{
  const SpiralSettings s = mm1();
  EXPECT_TRUE(mentions(inputError(test::cylinder(50, 100, 2, 5), s), "needs at least 3"));

  Generatrices g = test::cylinder(50, 100, 36, 5);
  g.lines[7].resize(1);
  g.normals[7].resize(1);
  EXPECT_TRUE(mentions(inputError(g, s), "generatrix 7 has 1 point"));

  g = test::cylinder(50, 100, 36, 5);
  g.lines[3][2].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(mentions(inputError(g, s), "generatrix 3, point 2 is not a finite position"));

  g = test::cylinder(50, 100, 36, 5);
  g.normals.pop_back();
  EXPECT_TRUE(mentions(inputError(g, s), "normals are given for 35 generatrices but there are 36"));

  g = test::cylinder(50, 100, 36, 5);
  g.normals[4].pop_back();
  EXPECT_TRUE(mentions(inputError(g, s), "generatrix 4 has 5 points but 4 normals"));

  g = test::cylinder(50, 100, 36, 5);
  g.normals[5][1] = Vec3::Zero();
  EXPECT_TRUE(mentions(inputError(g, s), "normal 1 of generatrix 5"));

  g = test::cylinder(50, 100, 36, 5);
  for (Vec3& p : g.lines[6]) p = g.lines[6][0];
  EXPECT_TRUE(mentions(inputError(g, s), "generatrix 6 has zero length"));
}

// 10 mm cannot hold the ±10 % start-up and termination (about 12 mm at h = 1 mm) plus a layer.
TEST(SpiralInput, RejectsGeneratricesTooShortForTheStartUp)
{
  const std::string e = inputError(test::cylinder(50, 10, 36, 5), mm1());
  EXPECT_TRUE(mentions(e, "generatrix 0 is 10 mm long")) << e;
  EXPECT_TRUE(mentions(e, "start-up")) << e;
  // 14 mm is enough: 9 + 1.0055 (3 * 36 - 1) / 36 = 11.99 mm of ramps and 2 layers of 1.0055 mm.
  NullProgress progress;
  const SpiralResult r = buildSpiral(test::cylinder(50, 14, 36, 5), mm1(), progress);
  EXPECT_EQ(r.report.nLayers, 2);
  EXPECT_NEAR(r.report.stepMin, (14.0 - 9.0) / (2.0 + 107.0 / 36.0), 1e-9);
}

TEST(SpiralInput, RejectsAClosedPartWhoseGeneratricesMissTheClosurePoint)
{
  Generatrices g = test::hemisphereMeridians(50, 36, 40);
  g.lines[9].back() += Vec3(0.0, 0.0, -3.0);
  EXPECT_TRUE(mentions(inputError(g, mm1()), "generatrix 9 ends 3 mm from the closure point"));
}

// Without normals, (next - previous generatrix) x (up the generatrix) gives the outward normal of
// a counter-clockwise cylinder.
TEST(SpiralInput, EstimatesMissingNormals)
{
  Generatrices g = test::cylinder(50, 30, 72, 7);
  g.normals.clear();
  NullProgress progress;
  const SpiralResult r = buildSpiral(g, mm1(), progress);
  EXPECT_TRUE(r.report.normalsEstimated);
  EXPECT_FALSE(r.report.normalsFlipped);
  for (const TrajectoryPoint& p : r.trajectory.points) {
    const Vec3 radial(p.position.x(), p.position.y(), 0.0);
    EXPECT_NEAR(p.normal.dot(radial.normalized()), 1.0, 1e-9);
    EXPECT_GT(p.build.z(), phaseOfRevolution(p.revolution, r.report) == SpiralPhase::Modulated ? 0.99 : 0.9);
  }
  // On a closed part the meridians meet at the pole; the normal there is copied from below.
  Generatrices dome = test::hemisphereMeridians(50, 72, 60);
  dome.normals.clear();
  const SpiralResult d = buildSpiral(dome, mm1(), progress);
  for (const TrajectoryPoint& p : d.trajectory.points) EXPECT_GT(p.normal.dot(p.position.normalized()), 0.99);
}

// Inward normals, or generatrices ordered clockwise, would make b = n x t point down: the normals
// are reversed so the build direction points up, away from the base.
TEST(SpiralInput, OrientsTheBuildDirectionUp)
{
  NullProgress progress;
  Generatrices inward = test::cylinder(50, 30, 72, 7);
  for (auto& line : inward.normals)
    for (Vec3& n : line) n = -n;
  const SpiralResult a = buildSpiral(inward, mm1(), progress);
  EXPECT_TRUE(a.report.normalsFlipped);

  Generatrices clockwise = test::cylinder(50, 30, 72, 7);
  std::reverse(clockwise.lines.begin(), clockwise.lines.end());
  std::reverse(clockwise.normals.begin(), clockwise.normals.end());
  const SpiralResult b = buildSpiral(clockwise, mm1(), progress);
  EXPECT_TRUE(b.report.normalsFlipped);

  for (const SpiralResult* r : {&a, &b}) {
    EXPECT_TRUE(r->report.feasible);
    for (const TrajectoryPoint& p : r->trajectory.points) {
      EXPECT_GT(p.build.z(),
                phaseOfRevolution(p.revolution, r->report) == SpiralPhase::Modulated ? 0.99 : 0.9);
      EXPECT_GT(p.height, 0.0);
    }
  }
  // Clockwise travel with b up: n points inward.
  const TrajectoryPoint& p = b.trajectory.points[0];
  EXPECT_LT(p.normal.dot(Vec3(p.position.x(), p.position.y(), 0).normalized()), -0.99);
}

// The decomposer sets the points per revolution (its points_per_rev): the spiral lays one point
// per generatrix and revolution, on the generatrix itself.
TEST(SpiralInput, LaysOnePointPerGeneratrixAndRevolution)
{
  NullProgress progress;
  const SpiralResult r = buildSpiral(test::cylinder(50, 30, 36, 7), mm1(), progress);
  EXPECT_EQ(r.report.pointsPerRevolution, 36);
  EXPECT_EQ(r.trajectory.size() % 36, 0u);
  for (const TrajectoryPoint& p : r.trajectory.points) EXPECT_NEAR(p.position.head<2>().norm(), 50.0, 1e-9);
}

TEST(SpiralInput, StopsWhenCancelled)
{
  CallbackProgress progress;
  progress.cancel();
  EXPECT_THROW(buildSpiral(test::cylinder(50, 30, 36, 7), mm1(), progress), Cancelled);
}
