// Deposit height -> travel speed / wire feed (thesis 000_dbb97c2716e10cc3.txt §4.2.1, Eq. 4.1; §4.3.1).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analytic_generatrices.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/path/dwell.h"
#include "spira/path/process_model.h"
#include "spira/path/spiral_builder.h"
#include "support/test_support.h"

using namespace spira;

namespace {

const double kWfs = 2.3 * toInternalFactor("m/min");  // 38.33 mm/s

// A modulated spiral: a part whose upper edge goes from 60 to 70 mm, at 2 mm ± 10 %.
Trajectory modulatedSpiral()
{
  SpiralSettings s;
  s.h = 2.0;
  s.hMin = 1.8;
  s.hMax = 2.2;
  s.layerMode = LayerMode::Centered;
  NullProgress progress;
  const Generatrices g = test::cylinderLines(
      40.0, 120, [](int i) { return 65.0 - 5.0 * std::cos(test::angleOf(i, 120)); }, 20);
  return buildSpiral(g, s, progress).trajectory;
}

// The thesis's 7-bead style table (made up, monotone): 1.7..2.3 mm -> 3.5..2.5 mm/s.
CalibrationTable sevenBeads()
{
  return CalibrationTable({1.7, 1.8, 1.9, 2.0, 2.1, 2.2, 2.3}, {3.5, 3.3, 3.1, 2.95, 2.8, 2.65, 2.5});
}

}  // namespace

// Eq. 4.1 with the wall width of Fig. 4.3: WFS 2.3 m/min, d = 1 mm, W = 5.2 mm -> TS = 3.22 / 2.89 / 2.63
// mm/s for 1.8 / 2.0 / 2.2 mm.
TEST(ProcessModel, MassConservationNumbers)
{
  EXPECT_NEAR(kWfs, 38.3333, 1e-4);
  EXPECT_NEAR(massConservationTravelSpeed(1.0, 5.2, kWfs, 1.8), 3.22, 0.005);
  EXPECT_NEAR(massConservationTravelSpeed(1.0, 5.2, kWfs, 2.0), 2.89, 0.005);
  EXPECT_NEAR(massConservationTravelSpeed(1.0, 5.2, kWfs, 2.2), 2.63, 0.005);
  // Eq. 4.1: pi d^2 / 4 * WFS = 30.1 mm^3/s, so LH * W * TS = 30.1.
  EXPECT_NEAR(massConservationHeight(1.0, 5.2, kWfs, 2.0) * 5.2 * 2.0, 30.1, 0.01);
  EXPECT_NEAR(massConservationHeight(1.0, 5.2, kWfs, massConservationTravelSpeed(1.0, 5.2, kWfs, 1.9)), 1.9,
              1e-12);
  EXPECT_NEAR(massConservationWireFeed(1.0, 5.2, massConservationTravelSpeed(1.0, 5.2, kWfs, 2.1), 2.1), kWfs,
              1e-12);
}

// Synergic: WFS constant, TS in phase opposition with h (h * TS constant under mass conservation).
TEST(ProcessModel, SynergicModulatesTravelSpeedAgainstHeight)
{
  Trajectory t = modulatedSpiral();
  ProcessSettings ps;
  ps.wireFeed = kWfs;
  const ProcessReport rep = applyProcess(t, ps);
  const double product = kPi / 4.0 * kWfs / 5.2;
  double length = 0.0, time = 0.0;
  for (size_t q = 0; q < t.size(); ++q) {
    const TrajectoryPoint& p = t.points[q];
    EXPECT_EQ(p.wireFeed, kWfs);
    EXPECT_NEAR(p.travelSpeed * p.height, product, 1e-9);
    EXPECT_TRUE(p.arcOn);
    if (q + 1 < t.size()) {
      const double seg = (t.points[q + 1].position - p.position).norm();
      length += seg;
      time += seg / p.travelSpeed;
    }
  }
  // Within a modulated revolution the thickest point is the slowest.
  size_t thick = 0, thin = 0;
  for (size_t q = 6 * 120; q < 7 * 120; ++q) {
    if (t.points[q].height > t.points[thick].height || thick < 6 * 120) thick = q;
    if (t.points[q].height < t.points[thin].height || thin < 6 * 120) thin = q;
  }
  EXPECT_GT(t.points[thick].height, t.points[thin].height + 0.1);
  EXPECT_LT(t.points[thick].travelSpeed, t.points[thin].travelSpeed);
  EXPECT_NEAR(rep.buildTime, time, 1e-9 * time);
  EXPECT_NEAR(rep.wireLength, kWfs * time, 1e-9 * kWfs * time);
  EXPECT_NEAR(rep.depositVolume, rep.wireLength * kPi / 4.0, 1e-9 * rep.depositVolume);
  EXPECT_EQ(rep.wireFeedMin, kWfs);
  EXPECT_NEAR(rep.travelSpeedMin, product / 2.2, 0.05);
  EXPECT_TRUE(rep.withinLimits);
}

// Constant TS: WFS proportional to h; build time is the path length over TS.
TEST(ProcessModel, ConstantTravelSpeedModulatesWireFeed)
{
  Trajectory t = modulatedSpiral();
  ProcessSettings ps;
  ps.mode = ProcessMode::ConstantTravelSpeed;
  ps.travelSpeed = 6.0;
  const ProcessReport rep = applyProcess(t, ps);
  for (const TrajectoryPoint& p : t.points) {
    EXPECT_EQ(p.travelSpeed, 6.0);
    EXPECT_NEAR(p.wireFeed, 4.0 * 5.2 * 6.0 * p.height / kPi, 1e-9);
  }
  EXPECT_NEAR(rep.buildTime, t.length() / 6.0, 1e-9 * rep.buildTime);
}

// The dwells' waits (path/dwell.h) are part of the build time.
TEST(ProcessModel, DwellsAddTheirWaitsToTheBuildTime)
{
  Trajectory plain = modulatedSpiral();
  ProcessSettings ps;
  ps.mode = ProcessMode::ConstantTravelSpeed;
  ps.travelSpeed = 6.0;
  const ProcessReport without = applyProcess(plain, ps);
  EXPECT_EQ(without.dwells, 0u);
  EXPECT_EQ(without.dwellTime, 0.0);
  Trajectory t = modulatedSpiral();
  std::vector<double> dwell(t.size(), 0.0);
  dwell[5] = 30.0;
  dwell[t.size() / 2] = 12.5;
  t.extra[kDwellChannel] = dwell;
  const ProcessReport rep = applyProcess(t, ps);
  EXPECT_EQ(rep.dwells, 2u);
  EXPECT_EQ(rep.dwellTime, 42.5);
  EXPECT_NEAR(rep.buildTime, without.buildTime + 42.5, 1e-9 * rep.buildTime);
  EXPECT_EQ(rep.wireLength, without.wireLength);  // no wire is fed during a wait
  EXPECT_EQ(t.points, plain.points);
}

TEST(ProcessModel, CalibrationTableInterpolatesPiecewiseLinearly)
{
  const CalibrationTable table = sevenBeads();
  EXPECT_DOUBLE_EQ(table.travelSpeed(1.8), 3.3);
  EXPECT_NEAR(table.travelSpeed(1.95), 0.5 * (3.1 + 2.95), 1e-12);
  EXPECT_NEAR(table.travelSpeed(2.175), 2.8 + 0.75 * (2.65 - 2.8), 1e-12);
  EXPECT_DOUBLE_EQ(table.travelSpeed(1.0), 3.5);  // beyond the table: end values
  EXPECT_DOUBLE_EQ(table.travelSpeed(3.0), 2.5);
  // Rows in any order are sorted by height.
  const CalibrationTable shuffled({2.0, 1.8, 2.2}, {2.9, 3.2, 2.6});
  EXPECT_EQ(shuffled.heights(), (std::vector<double>{1.8, 2.0, 2.2}));
  EXPECT_NEAR(shuffled.travelSpeed(1.9), 3.05, 1e-12);

  Trajectory t = modulatedSpiral();
  ProcessSettings ps;
  ps.model = HeightModel::Calibration;
  ps.calibration = table;
  const ProcessReport rep = applyProcess(t, ps);
  size_t outside = 0;
  for (size_t q = 0; q < t.size(); ++q) {
    EXPECT_NEAR(t.points[q].travelSpeed, table.travelSpeed(t.points[q].height), 1e-12);
    outside += !table.covers(t.points[q].height);
  }
  size_t flagged = 0;
  for (const ProcessViolation& v : rep.violations)
    flagged += v.kind == ProcessViolationKind::HeightOutsideCalibration;
  EXPECT_EQ(flagged, outside);

  // Constant TS with the table: WFS = WFS_table * TS / TS_table(h).
  ps.mode = ProcessMode::ConstantTravelSpeed;
  ps.travelSpeed = 3.0;
  applyProcess(t, ps);
  for (const TrajectoryPoint& p : t.points)
    EXPECT_NEAR(p.wireFeed, ps.wireFeed * 3.0 / table.travelSpeed(p.height), 1e-9);
}

TEST(ProcessModel, CalibrationTableReadsBackTheHeightOfASpeed)
{
  const CalibrationTable table = sevenBeads();
  for (double h = 1.7; h <= 2.3; h += 0.01) EXPECT_NEAR(table.height(table.travelSpeed(h)), h, 1e-12) << h;
  EXPECT_DOUBLE_EQ(table.height(3.3), 1.8);
  EXPECT_NEAR(table.height(0.5 * (3.1 + 2.95)), 1.95, 1e-12);
  EXPECT_DOUBLE_EQ(table.height(9.0), 1.7);  // beyond the table: end values
  EXPECT_DOUBLE_EQ(table.height(1.0), 2.3);
}

TEST(ProcessModel, CalibrationTableRejectsNonMonotoneSpeeds)
{
  try {
    CalibrationTable({1.8, 1.9, 2.0, 2.1}, {3.3, 3.1, 3.15, 2.8});
    FAIL() << "a travel speed rising with the height was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("1.9 -> 2 mm"), std::string::npos) << what;
    EXPECT_NE(what.find("rows 2 and 3"), std::string::npos) << what;
    EXPECT_FALSE(e.hint().empty());
  }
  EXPECT_THROW(CalibrationTable({1.8, 2.0}, {3.0, 3.0}), InputError);   // flat
  EXPECT_THROW(CalibrationTable({1.8, 1.8}, {3.2, 3.0}), InputError);   // repeated height
  EXPECT_THROW(CalibrationTable({1.8}, {3.0}), InputError);             // one row
  EXPECT_THROW(CalibrationTable({1.8, 2.0}, {3.0}), InputError);        // sizes
  EXPECT_THROW(CalibrationTable({1.8, 2.0}, {3.0, -1.0}), InputError);  // negative
}

TEST(ProcessModel, ReadsCalibrationCsv)
{
  std::istringstream in(
      "# beads at 2.3 m/min\n"
      "bead,travel_speed_mm_s,height_mm\n"
      "\n"
      "a, 3.3, 1.8\n"
      "b,2.95,2.0\n"
      "c,2.65,2.2\n");
  const CalibrationTable t = parseCalibrationCsv(in, "beads.csv");
  EXPECT_EQ(t.size(), 3u);
  EXPECT_EQ(t.heights(), (std::vector<double>{1.8, 2.0, 2.2}));
  EXPECT_EQ(t.travelSpeeds(), (std::vector<double>{3.3, 2.95, 2.65}));

  std::istringstream badNumber("height_mm,travel_speed_mm_s\n1.8,3.3\n2.0,fast\n");
  try {
    parseCalibrationCsv(badNumber, "beads.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("beads.csv, line 3: 'fast' is not a number"), std::string::npos)
        << e.what();
  }
  std::istringstream noHeader("1.8,3.3\n2.0,2.9\n");
  EXPECT_THROW(parseCalibrationCsv(noHeader, "x.csv"), InputError);
  std::istringstream rising("height_mm,travel_speed_mm_s\n1.8,3.0\n2.0,3.1\n");
  EXPECT_THROW(parseCalibrationCsv(rising, "x.csv"), InputError);

  test::TempDir dir;
  test::writeBytes(dir / "table.csv", "height_mm,travel_speed_mm_s\r\n1.8,3.22\r\n2.2,2.63\r\n");
  EXPECT_NEAR(readCalibrationCsv((dir / "table.csv").string()).travelSpeed(2.0), 0.5 * (3.22 + 2.63), 1e-12);
  EXPECT_THROW(readCalibrationCsv((dir / "missing.csv").string()), IoError);
}

// Limits are checked point by point; crossing them is reported, not thrown, and the speed is
// clamped to the limit unless asked otherwise.
TEST(ProcessModel, ReportsLimitViolationsByPoint)
{
  Trajectory t = modulatedSpiral();
  ProcessSettings ps;
  ps.limits.travelSpeedMax = 2.9;  // thin deposits need more
  ps.limits.wireFeedMin = 10.0;
  const double product = kPi / 4.0 * ps.wireFeed / 5.2;  // TS * h, mass conservation
  size_t fast = 0;
  for (const TrajectoryPoint& p : t.points) fast += product / p.height > 2.9;
  ASSERT_GT(fast, 0u);
  ASSERT_LT(fast, t.size());

  const ProcessReport rep = applyProcess(t, ps);
  EXPECT_EQ(rep.violations.size(), fast);
  for (const ProcessViolation& v : rep.violations) {
    EXPECT_EQ(v.kind, ProcessViolationKind::TravelSpeedAboveMax);
    EXPECT_NEAR(v.value, product / t.points[v.point].height, 1e-9);
    EXPECT_EQ(v.limit, 2.9);
    EXPECT_EQ(t.points[v.point].travelSpeed, 2.9);
  }
  EXPECT_EQ(rep.travelSpeedMax, 2.9);
  EXPECT_FALSE(rep.withinLimits);

  ps.clampToLimits = false;
  applyProcess(t, ps);
  for (const ProcessViolation& v : rep.violations) EXPECT_EQ(t.points[v.point].travelSpeed, v.value);

  ps.limits = {};
  ps.limits.wireFeedMax = 30.0;  // the held 38.3 mm/s is too much everywhere
  EXPECT_EQ(applyProcess(t, ps).violations.size(), t.size());
}

// A whole hemisphere plan, ramps and closure point included: every deposit lies in the window, so
// every synergic travel speed lies between the mass-conservation speeds of h_max and h_min
// (TS = pi d^2 WFS / (4 W h)), and none reaches a 20 mm/s limit.
TEST(ProcessModel, ClosedPartSpeedsFollowTheWindowToTheClosurePoint)
{
  SpiralSettings s;
  s.h = 1.0;
  s.hMin = 0.9;
  s.hMax = 1.1;
  NullProgress progress;
  Trajectory t = buildSpiral(test::hemisphereMeridians(50.0, 360, 100), s, progress).trajectory;
  ProcessSettings ps;
  ps.limits.travelSpeedMax = 20.0;
  const ProcessReport rep = applyProcess(t, ps);
  EXPECT_TRUE(rep.withinLimits);
  EXPECT_TRUE(rep.violations.empty());
  const auto speedAt = [&](double h) {
    return kPi * ps.wireDiameter * ps.wireDiameter * ps.wireFeed / (4.0 * ps.beadWidth * h);
  };
  const double tol = s.heightTolerance * s.h;
  for (const TrajectoryPoint& p : t.points) {
    EXPECT_GE(p.travelSpeed, speedAt(s.hMax + tol) - 1e-12);
    EXPECT_LE(p.travelSpeed, speedAt(s.hMin - tol) + 1e-12);
    EXPECT_NEAR(p.travelSpeed, speedAt(p.height), 1e-9);
  }
  EXPECT_NEAR(t.points.back().travelSpeed, t.points[t.size() - 2].travelSpeed, 1e-12);
  EXPECT_TRUE(std::isfinite(rep.buildTime));
}

TEST(ProcessModel, RejectsBadSettings)
{
  Trajectory t = modulatedSpiral();
  ProcessSettings ps;
  ps.wireDiameter = 0.0;
  EXPECT_THROW(applyProcess(t, ps), InputError);
  ps = {};
  ps.beadWidth = -5.0;
  EXPECT_THROW(applyProcess(t, ps), InputError);
  ps = {};
  ps.wireFeed = 0.0;
  EXPECT_THROW(applyProcess(t, ps), InputError);
  ps = {};
  ps.mode = ProcessMode::ConstantTravelSpeed;
  ps.travelSpeed = std::nan("");
  EXPECT_THROW(applyProcess(t, ps), InputError);
  ps = {};
  ps.model = HeightModel::Calibration;
  EXPECT_THROW(applyProcess(t, ps), InputError);
  ps = {};
  ps.limits.travelSpeedMin = 5.0;
  ps.limits.travelSpeedMax = 4.0;
  EXPECT_THROW(applyProcess(t, ps), InputError);
}

// A point that did not move along its generatrix has no height: it keeps its neighbour's speeds.
TEST(ProcessModel, PointsWithoutHeightKeepTheNeighbourSpeeds)
{
  Trajectory t = modulatedSpiral();
  t.points[0].height = 0.0;
  t.points[10].height = -1.0;
  ProcessSettings ps;
  const ProcessReport rep = applyProcess(t, ps);
  EXPECT_EQ(t.points[0].travelSpeed, t.points[1].travelSpeed);
  EXPECT_EQ(t.points[10].travelSpeed, t.points[9].travelSpeed);
  size_t flagged = 0;
  for (const ProcessViolation& v : rep.violations)
    flagged += v.kind == ProcessViolationKind::HeightNotPositive;
  EXPECT_EQ(flagged, 2u);
}

namespace spira {
namespace {

std::string calibrationRefusal(const std::string& text)
{
  std::istringstream in(text);
  try {
    parseCalibrationCsv(in, "beads.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(CalibrationTableInput, AHugeBadCellIsQuotedClipped)
{
  const std::string huge(1 << 20, 'x');
  const std::string message = calibrationRefusal("height_mm,travel_speed_mm_s\n1.8," + huge + "\n");
  EXPECT_EQ(message, "beads.csv, line 2: '" + std::string(60, 'x') + "...' is not a number");
}

TEST(CalibrationTableInput, NonFiniteAndOverflowingNumbersAreNamed)
{
  EXPECT_EQ(calibrationRefusal("height_mm,travel_speed_mm_s\n1.8,inf\n"),
            "beads.csv, line 2: 'inf' is not a finite number");
  EXPECT_EQ(calibrationRefusal("height_mm,travel_speed_mm_s\n1e999,3\n"),
            "beads.csv, line 2: '1e999' is beyond the range of a double (about 1.8e308)");
}

}  // namespace
}  // namespace spira
