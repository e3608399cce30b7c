// Where the spiral's seam goes on generatrices that lean along the travel.
#include <gtest/gtest.h>

#include <cmath>

#include "analytic_generatrices.h"
#include "spira/base/progress.h"
#include "spira/path/seam_placement.h"
#include "spira/path/spiral_builder.h"
#include "spira/verify/deposit_check.h"
#include "spiral_window.h"

using namespace spira;

namespace {

constexpr int kN = 120;
constexpr double kR = 20.0, kHeight = 40.0, kLean = 15.0 * kPi / 180.0;

// The circle of radius kR on the substrate swept along (sin lean, 0, cos lean), generatrix i at
// phi = phi0 + 2 pi i / n. The ring's tangent at phi is (-sin phi, cos phi, 0), so a generatrix
// leans along the travel by sin(lean) sin(phi): most at phi = +-90 degrees, not at 0 and 180.
Generatrices obliqueTube(double phi0)
{
  Generatrices g;
  const int points = 81;
  for (int i = 0; i < kN; ++i) {
    const double phi = phi0 + test::angleOf(i, kN);
    const Vec3 normal = Vec3(std::cos(phi), std::sin(phi), -std::cos(phi) * std::tan(kLean)).normalized();
    Polyline line;
    std::vector<Vec3> normals;
    for (int k = 0; k < points; ++k) {
      const double z = kHeight * k / (points - 1);
      line.emplace_back(kR * std::cos(phi) + z * std::tan(kLean), kR * std::sin(phi), z);
      normals.push_back(normal);
    }
    g.lines.push_back(line);
    g.normals.push_back(normals);
  }
  return g;
}

double phiOf(int i, double phi0)
{
  return phi0 + test::angleOf(i, kN);
}

}  // namespace

TEST(SeamPlacement, GoesWhereTheGeneratricesDoNotLeanAlongTheTravel)
{
  const double phi0 = 0.5 * kPi;  // generatrix 0 leans the most
  const int seam = leastLeaningSeam(obliqueTube(phi0), 8.0);
  EXPECT_LT(std::abs(std::sin(phiOf(seam, phi0))), std::sin(test::angleOf(1, kN))) << seam;
  // Where generatrix 0 already leans the least, the seam stays.
  EXPECT_EQ(leastLeaningSeam(obliqueTube(0.0), 8.0), 0);
  EXPECT_EQ(leastLeaningSeam(test::cylinder(kR, kHeight, kN, 41), 8.0), 0);
}

// Numbered from its most leaning generatrix, the tube is laid with its seam where it does not lean,
// and every bead passes the deposit check. The points keep the given generatrix numbers.
TEST(SeamPlacement, ObliqueTubeLaidFromItsMostLeaningGeneratrixPassesTheDepositCheck)
{
  const double phi0 = 0.5 * kPi;
  const Generatrices g = obliqueTube(phi0);
  const SpiralSettings s = test::thesisWindow();
  NullProgress progress;
  const SpiralResult r = buildSpiral(g, s, progress);
  const Trajectory& t = r.trajectory;
  const int seam = t.points.front().generatrix;
  EXPECT_EQ(seam, leastLeaningSeam(g, 8.0));
  EXPECT_LT(std::abs(std::sin(phiOf(seam, phi0))), std::sin(test::angleOf(1, kN)));
  EXPECT_EQ(t.points[1].generatrix, (seam + 1) % kN);
  EXPECT_NEAR(t.points.front().position.y(), g.lines[seam].front().y(), 1e-9);

  DepositCheckSettings c;
  c.hMin = s.hMin;
  c.hMax = s.hMax;
  c.tolerance = 0.01;
  c.beadWidth = 4.0;
  const DepositCheckReport d = checkDeposits(t, nullptr, c, progress);
  EXPECT_TRUE(d.feasible) << d.summary();
}
