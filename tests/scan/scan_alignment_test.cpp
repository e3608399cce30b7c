// Registration and deviation against independent truth: a scan moved by a known rigid transform comes
// back to it, and a scan of the part grown by 1 % lies the analytic distance off it.
#include <gtest/gtest.h>

#include "builtin_plugins.h"

#include <cmath>
#include <cstdio>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/io/import_service.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/scan/scan_alignment.h"
#include "spira/scan/scan_deviation.h"
#include "spira/scan/scan_simulator.h"
#include "support/test_support.h"

namespace spira {
namespace {

// A real part: the T-junction of tubes of tests/data/real (SOURCES.md), in mm. A body of revolution
// would let the fit slide or turn along itself; the junction holds it in every direction.
TriangleMesh junction()
{
  NullProgress progress;
  return importPart(builtinRegistry(), test::sourceDir() / "tests/data/real/junction_waam_mm.stl", nullptr,
                    progress)
      .mesh;
}

Transform moved(double mm, double deg)
{
  Transform T = Transform::Identity();
  T.linear() = Eigen::AngleAxisd(degToRad(deg), Vec3(0.3, -0.8, 0.5).normalized()).toRotationMatrix();
  T.translation() = mm * Vec3(0.6, 0.48, -0.64);
  return T;
}

TEST(ScanAlignment, AScanMovedFiveMillimetresAndFiveDegreesComesBack)
{
  const TriangleMesh part = junction();
  ScanErrors errors;
  errors.noiseMm = 0.05;
  errors.misalignment = moved(5.0, 5.0);
  const PointCloud scan = simulateSurfaceScan(part, 0.7, errors, 7);
  NullProgress progress;
  const AlignResult fit = alignScan(scan, part, Transform::Identity(), AlignSettings{}, progress);
  // The fit undoes the misalignment: T_part_scan * misalignment is the identity.
  const Transform error = fit.T_part_scan * errors.misalignment;
  const double mm = error.translation().norm();
  const double deg = radToDeg(Eigen::AngleAxisd(error.linear()).angle());
  // The point of the part farthest from its centre moves by both.
  double far = 0.0;
  for (const Vec3& v : part.vertices) far = std::max(far, (error * v - v).norm());
  std::printf(
      "aligned %zu points: off by %.4f mm and %.4f deg (%.4f mm at most on the part), residual %.4f mm, %.1f "
      "%% "
      "matched\n",
      scan.size(), mm, deg, far, fit.rmsMm, 100.0 * fit.inlierFraction);
  EXPECT_LT(mm, 0.02);
  EXPECT_LT(deg, 0.02);
  EXPECT_LT(far, 0.02);
  // The noise, less what the 1 mm cells average out of it.
  EXPECT_LT(fit.rmsMm, 0.05);
  EXPECT_GT(fit.rmsMm, 0.02);
  EXPECT_GT(fit.inlierFraction, 0.99);
}

TEST(ScanAlignment, TooFewPointsOrNoOverlapAreRefused)
{
  const TriangleMesh part = junction();
  NullProgress progress;
  PointCloud few;
  for (int i = 0; i < 20; ++i) few.points.push_back(Vec3(15.0, 0.0, i));
  try {
    alignScan(few, part, Transform::Identity(), AlignSettings{}, progress);
    FAIL() << "20 points were aligned";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("aligning needs 100"), std::string::npos) << e.what();
  }
  ScanErrors far;
  far.misalignment.translation() = Vec3(300.0, 0.0, 0.0);
  try {
    alignScan(simulateSurfaceScan(part, 1.5, far), part, Transform::Identity(), AlignSettings{}, progress);
    FAIL() << "a scan 300 mm away was aligned";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not overlap the part"), std::string::npos) << e.what();
  }
}

// An open cylinder (R 50, H 100) scanned after growing by 1 % about its base centre: every point of
// the wall below the nominal top lies 0.5 mm outside, the radius's 1 %, give or take the noise and the
// mesh's chords (0.002 mm at 360 segments).
TEST(ScanDeviation, AScanOfThePartGrownByOnePercentLiesTheAnalyticDistanceOutside)
{
  const TriangleMesh part = makeOpenCylinder(50.0, 100.0, 360, 100);
  ScanErrors errors;
  errors.scale = 1.01;
  errors.noiseMm = 0.01;
  const PointCloud scan = simulateSurfaceScan(part, 1.0, errors, 3);
  NullProgress progress;
  const std::vector<double> d = scanDeviation(scan, part, progress);
  ASSERT_EQ(d.size(), scan.size());
  std::vector<double> wall;
  double worst = 0.0;
  for (size_t i = 0; i < d.size(); ++i) {
    if (scan.points[i].z() > 99.0) continue;  // above the nominal top edge: measured to the edge
    wall.push_back(d[i]);
    worst = std::max(worst, std::abs(d[i] - 0.5));
  }
  const DeviationStats s = deviationStats(wall);
  std::printf("grown cylinder: %zu wall points, mean %.4f mm, RMS %.4f, p95 %.4f, worst off 0.5 by %.4f\n",
              s.count, s.mean, s.rms, s.p95, worst);
  EXPECT_NEAR(s.mean, 0.5, 0.003);
  EXPECT_LT(worst, 0.002 + 6 * 0.01);
  EXPECT_NEAR(s.p95, 0.5 + 1.645 * 0.01, 0.01);
  // Shrunk instead: inside, negative.
  errors.scale = 0.99;
  const std::vector<double> inside = scanDeviation(simulateSurfaceScan(part, 2.0, errors, 4), part, progress);
  EXPECT_NEAR(deviationStats(inside).mean, -0.5, 0.01);
}

TEST(ScanDeviation, StatisticsAndHistogramOfKnownValues)
{
  std::vector<double> d;
  for (int i = -50; i <= 49; ++i) d.push_back(0.01 * i);  // -0.50 .. 0.49
  const DeviationStats s = deviationStats(d, 10);
  EXPECT_EQ(s.count, 100u);
  EXPECT_NEAR(s.mean, -0.005, 1e-12);
  EXPECT_NEAR(s.rms, std::sqrt(0.08335), 1e-6);
  EXPECT_NEAR(s.p95, 0.47, 1e-12);  // the 95th of the magnitudes 0.00, 0.01, 0.01, ..., 0.49, 0.50
  EXPECT_EQ(s.min, -0.5);
  EXPECT_EQ(s.max, 0.49);
  ASSERT_EQ(s.histogram.size(), 10u);
  size_t total = 0;
  for (size_t c : s.histogram) {
    total += c;
    EXPECT_GE(c, 9u);
  }
  EXPECT_EQ(total, 100u);
}

TEST(ScanUnits, AScanInOtherUnitsIsNamed)
{
  BoundingBox part;
  part.extend(Vec3(0, 0, 0));
  part.extend(Vec3(100, 100, 100));
  const auto box = [](double s) {
    BoundingBox b;
    b.extend(Vec3(0, 0, 0));
    b.extend(Vec3(s, s, s));
    return b;
  };
  EXPECT_FALSE(scanUnitHint(box(104.0), part));
  EXPECT_FALSE(scanUnitHint(box(40.0), part));  // a partly built wall, a substrate corner
  const auto inches = scanUnitHint(box(100.0 / 25.4), part);
  ASSERT_TRUE(inches);
  EXPECT_NE(inches->find("likely in inches (scale it by 25.4"), std::string::npos) << *inches;
  const auto metres = scanUnitHint(box(0.1), part);
  ASSERT_TRUE(metres);
  EXPECT_NE(metres->find("metres (scale it by 1000"), std::string::npos) << *metres;
  const auto micro = scanUnitHint(box(100000.0), part);
  ASSERT_TRUE(micro);
  EXPECT_NE(micro->find("1000 times larger"), std::string::npos) << *micro;
}

}  // namespace
}  // namespace spira
