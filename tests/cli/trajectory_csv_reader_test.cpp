#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/path/dwell.h"
#include "spira/path/tool_tilt.h"
#include "spira/planning/plan_files.h"
#include "spira/planning/trajectory_csv_reader.h"

namespace spira {
namespace {

Trajectory awkwardTrajectory()
{
  Trajectory t;
  for (int i = 0; i < 50; ++i) {
    TrajectoryPoint p;
    const double a = 0.1234567891 * i;
    p.position = Vec3(50.0 * std::cos(a), 50.0 * std::sin(a), 0.1 * i + 1e-9);
    p.normal = Vec3(std::cos(a), std::sin(a), 0.0);
    p.tangent = Vec3(-std::sin(a), std::cos(a), 0.0);
    p.build = p.normal.cross(p.tangent);
    p.revolution = i / 7;
    p.generatrix = i % 7;
    p.height = 1.0 + 0.1 * std::sin(a);
    p.travelSpeed = 5.0 + 1.0 / 3.0;
    p.wireFeed = 2300.0 / 60.0 + 0.01 * i;
    p.arcOn = i != 49;
    p.path = i / 20;
    t.points.push_back(p);
  }
  return t;
}

TEST(TrajectoryCsvReader, ReadsBackWhatThePlanWrote)
{
  const Trajectory t = awkwardTrajectory();
  const Trajectory back = trajectoryFromCsv(trajectoryCsv(t));
  ASSERT_EQ(back.size(), t.size());
  for (size_t i = 0; i < t.size(); ++i) {
    const TrajectoryPoint& a = t.points[i];
    const TrajectoryPoint& b = back.points[i];
    EXPECT_EQ(a.position, b.position);  // shortest round-trip numbers: exact
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_EQ(a.build, b.build);
    EXPECT_EQ(a.revolution, b.revolution);
    EXPECT_EQ(a.generatrix, b.generatrix);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.travelSpeed, b.travelSpeed);
    EXPECT_NEAR(a.wireFeed, b.wireFeed, 1e-12 * a.wireFeed);  // through m/min and back
    EXPECT_EQ(a.arcOn, b.arcOn);
    EXPECT_EQ(a.path, b.path);
  }
  EXPECT_EQ(back.points.back().path, 2);
}

// Plans written before sub-paths existed have no path column: they read as one path.
TEST(TrajectoryCsvReader, ReadsFilesWithoutThePathColumnAsOnePath)
{
  std::string text = trajectoryCsv(awkwardTrajectory());
  std::string old;
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t end = text.find('\n', pos);
    std::string line = text.substr(pos, end - pos);
    line.erase(line.rfind(','));  // drop the last column
    old += line + "\n";
    pos = end + 1;
  }
  ASSERT_EQ(old.substr(0, old.find('\n')),
            "index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc");
  const Trajectory back = trajectoryFromCsv(old);
  const Trajectory t = awkwardTrajectory();
  ASSERT_EQ(back.size(), t.size());
  for (size_t i = 0; i < t.size(); ++i) {
    EXPECT_EQ(back.points[i].position, t.points[i].position);
    EXPECT_EQ(back.points[i].arcOn, t.points[i].arcOn);
    EXPECT_EQ(back.points[i].path, 0);
  }
}

TEST(TrajectoryCsvReader, BadFilesNameTheLine)
{
  const std::string good = trajectoryCsv(awkwardTrajectory());
  const auto expectLine = [](const std::string& text, const std::string& mention) {
    try {
      trajectoryFromCsv(text);
      FAIL() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
    }
  };
  expectLine("", "empty");
  expectLine("index,x,y\n", "header");
  std::string shortRow = good;
  shortRow.insert(shortRow.find('\n') + 1, "0,1,2\n");
  expectLine(shortRow, "line 2");
  std::string badNumber = good;
  badNumber.replace(badNumber.find('\n') + 3, 1, "x");
  expectLine(badNumber, "line 2");
  std::string skipped = good;
  const size_t second = skipped.find('\n', skipped.find('\n') + 1) + 1;
  skipped.erase(second, skipped.find('\n', second) + 1 - second);
  expectLine(skipped, "index");
  std::string badPath = good;
  const size_t row2 = badPath.find('\n') + 1;
  const size_t rowEnd = badPath.find('\n', row2);
  badPath.replace(badPath.rfind(',', rowEnd) + 1, rowEnd - badPath.rfind(',', rowEnd) - 1, "0.5");
  expectLine(badPath, "sub-path");
}

}  // namespace
}  // namespace spira

namespace spira {
namespace {

// The CSV of awkwardTrajectory() with the value of `column` (0-based) on data row `row` (0-based)
// replaced by `value`.
std::string withCell(size_t row, int column, const std::string& value)
{
  std::string text = trajectoryCsv(awkwardTrajectory());
  size_t start = text.find('\n') + 1;
  for (size_t r = 0; r < row; ++r) start = text.find('\n', start) + 1;
  for (int c = 0; c < column; ++c) start = text.find(',', start) + 1;
  const size_t end = text.find_first_of(",\n", start);
  text.replace(start, end - start, value);
  return text;
}

std::string refusal(const std::string& text)
{
  try {
    trajectoryFromCsv(text, "plan/trajectory.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(TrajectoryCsvValidation, PathNumbersGoUpByOneFromZero)
{
  // Row 30 is on path 1 (rows 20..39); a 0 there goes back, a 3 skips.
  EXPECT_EQ(
      refusal(withCell(30, 19, "0")),
      "plan/trajectory.csv line 32: column 20 (path) must stay 1 or go on to 2 (sub-paths are numbered in "
      "order from 0), found 0");
  EXPECT_NE(refusal(withCell(30, 19, "3")).find("line 32: column 20 (path) must stay 1 or go on to 2"),
            std::string::npos);
  EXPECT_NE(refusal(withCell(0, 19, "1")).find("line 2: column 20 (path) must be 0 on the first row"),
            std::string::npos);
  EXPECT_NE(refusal(withCell(5, 19, "-1")).find("line 7: column 20 (path) must be a sub-path number"),
            std::string::npos);
}

TEST(TrajectoryCsvValidation, SpeedsArePositiveOnEveryRow)
{
  EXPECT_EQ(refusal(withCell(17, 16, "0")),
            "plan/trajectory.csv line 19: column 17 (ts) must be a positive travel speed in mm/s, found 0");
  EXPECT_NE(refusal(withCell(3, 16, "-5")).find("line 5: column 17 (ts) must be a positive"),
            std::string::npos);
  EXPECT_NE(refusal(withCell(3, 17, "0")).find("line 5: column 18 (wfs) must be a positive wire-feed speed"),
            std::string::npos);
  // Row 49 has the arc off: no wire is fed, so 0 is fine, a negative speed is not.
  EXPECT_EQ(refusal(withCell(49, 17, "0")), "accepted");
  EXPECT_NE(refusal(withCell(49, 17, "-1")).find("line 51: column 18 (wfs) must not be negative"),
            std::string::npos);
}

TEST(TrajectoryCsvValidation, EveryValueIsFiniteAndNamed)
{
  EXPECT_EQ(refusal(withCell(10, 2, "inf")),
            "plan/trajectory.csv line 12: column 3 (y) is not a finite number, "
            "found 'inf'");
  EXPECT_NE(refusal(withCell(10, 15, "nan")).find("line 12: column 16 (height) is not a finite number"),
            std::string::npos);
  EXPECT_NE(refusal(withCell(10, 18, "2")).find("line 12: column 19 (arc) must be 0 or 1, found 2"),
            std::string::npos);
  EXPECT_NE(refusal(withCell(10, 13, "1.5")).find("line 12: column 14 (rev) must be a whole number from 0"),
            std::string::npos);
  const std::string huge(5000, '9');
  const std::string clipped = refusal(withCell(10, 1, huge + "x"));
  EXPECT_NE(clipped.find("found '" + std::string(60, '9') + "...'"), std::string::npos) << clipped.size();
  EXPECT_LT(clipped.size(), 200u);
}

}  // namespace
}  // namespace spira

namespace spira {
namespace {

// awkwardTrajectory() with a 12.5 s dwell at point 10 and a 0.25 s one at point 33.
Trajectory dwellTrajectory()
{
  Trajectory t = awkwardTrajectory();
  std::vector<double> dwell(t.size(), 0.0);
  dwell[10] = 12.5;
  dwell[33] = 0.25;
  t.extra[kDwellChannel] = dwell;
  return t;
}

TEST(TrajectoryCsvDwell, TheColumnIsWrittenOnlyWithADwell)
{
  const std::string plain = trajectoryCsv(awkwardTrajectory());
  Trajectory zeros = awkwardTrajectory();
  zeros.extra[kDwellChannel] = std::vector<double>(zeros.size(), 0.0);
  EXPECT_EQ(trajectoryCsv(zeros), plain);  // a channel of zeros plans no dwell

  const std::string text = trajectoryCsv(dwellTrajectory());
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc,path,dwell_s");
  // Every line is the plain one plus the wait: 12.5 on row 10 (line 12), 0 on rows without a dwell.
  std::string stripped, lastColumns;
  for (size_t pos = text.find('\n') + 1; pos < text.size();) {
    const size_t end = text.find('\n', pos);
    const size_t comma = text.rfind(',', end);
    stripped += text.substr(pos, comma - pos) + "\n";
    lastColumns += text.substr(comma + 1, end - comma - 1) + " ";
    pos = end + 1;
  }
  EXPECT_EQ(plain.substr(0, plain.find('\n') + 1) + stripped, plain);
  std::string expected;
  for (size_t i = 0; i < 50; ++i) expected += i == 10 ? "12.5 " : i == 33 ? "0.25 " : "0 ";
  EXPECT_EQ(lastColumns, expected);
}

TEST(TrajectoryCsvDwell, ReadsBackTheChannel)
{
  const Trajectory t = dwellTrajectory();
  const Trajectory back = trajectoryFromCsv(trajectoryCsv(t));
  ASSERT_EQ(back.size(), t.size());
  ASSERT_EQ(back.extra.count(kDwellChannel), 1u);
  EXPECT_EQ(back.extra.at(kDwellChannel), t.extra.at(kDwellChannel));
  EXPECT_EQ(dwellAt(back, 10), 12.5);
  EXPECT_EQ(dwellAt(back, 33), 0.25);
  EXPECT_EQ(back.points[33].path, 1);
  // A column of zeros plans no dwell: no channel, as when the column is not there.
  std::string zeros = trajectoryCsv(t);
  for (const char* wait : {",12.5\n", ",0.25\n"}) zeros.replace(zeros.find(wait), std::strlen(wait), ",0\n");
  EXPECT_EQ(trajectoryFromCsv(zeros).extra.count(kDwellChannel), 0u);
  // Without the column there is no channel at all.
  EXPECT_EQ(trajectoryFromCsv(trajectoryCsv(awkwardTrajectory())).extra.count(kDwellChannel), 0u);
}

// The CSV of dwellTrajectory() with the dwell of data row `row` (0-based) replaced by `value`.
std::string withDwell(size_t row, const std::string& value)
{
  std::string text = trajectoryCsv(dwellTrajectory());
  size_t start = text.find('\n') + 1;
  for (size_t r = 0; r < row; ++r) start = text.find('\n', start) + 1;
  const size_t end = text.find('\n', start);
  const size_t comma = text.rfind(',', end) + 1;
  text.replace(comma, end - comma, value);
  return text;
}

TEST(TrajectoryCsvDwell, DwellsAreFiniteWaitsWhereTheArcBurns)
{
  EXPECT_EQ(refusal(withDwell(12, "-1")),
            "plan/trajectory.csv line 14: column 21 (dwell_s) must be a wait in s from 0, found -1");
  EXPECT_NE(refusal(withDwell(12, "inf")).find("line 14: column 21 (dwell_s) is not a finite number"),
            std::string::npos);
  // Row 49 has the arc off: the torch is not depositing there, so it cannot stop the arc there.
  EXPECT_EQ(refusal(withDwell(49, "3")),
            "plan/trajectory.csv line 51: column 21 (dwell_s) must be 0 where the arc is off (a dwell stops "
            "the arc), found 3");
  EXPECT_EQ(refusal(withDwell(49, "0")), "accepted");
  EXPECT_EQ(trajectoryFromCsv(withDwell(12, "4")).extra.at(kDwellChannel)[12], 4.0);
  // A row one column short of the dwell header is refused like any short row.
  std::string shortRow = trajectoryCsv(dwellTrajectory());
  const size_t row0 = shortRow.find('\n') + 1;
  const size_t end0 = shortRow.find('\n', row0);
  shortRow.erase(shortRow.rfind(',', end0), end0 - shortRow.rfind(',', end0));
  EXPECT_NE(refusal(shortRow).find("line 2: expected 21 columns"), std::string::npos) << refusal(shortRow);
}

// A tilted torch's plan carries the build direction the positioner keeps vertical (tool_tilt.h), after
// the dwell when there is one; it reads back exactly, and a zero direction is refused with its line.
TEST(TrajectoryCsvUp, TheBuildDirectionOfATiltedTorchReadsBack)
{
  for (const Trajectory& source : {awkwardTrajectory(), dwellTrajectory()}) {
    const Trajectory t = withTorchTilt(source, TorchTilt{degToRad(12.0), degToRad(-4.0)});
    const std::string text = trajectoryCsv(t);
    const std::string header = text.substr(0, text.find('\n'));
    EXPECT_EQ(header.substr(header.size() - 9), ",ux,uy,uz");
    EXPECT_EQ(header.find(",dwell_s") != std::string::npos, hasDwell(t));
    const Trajectory back = trajectoryFromCsv(text);
    ASSERT_EQ(back.size(), t.size());
    for (size_t i = 0; i < t.size(); ++i) {
      EXPECT_EQ(back.points[i].build, t.points[i].build);
      EXPECT_EQ(upDirection(back, i), source.points[i].build);
      EXPECT_EQ(dwellAt(back, i), dwellAt(t, i));
    }
  }
  std::string text = trajectoryCsv(withTorchTilt(awkwardTrajectory(), TorchTilt{degToRad(12.0), 0.0}));
  const size_t row3 = text.find("\n3,") + 1;
  const size_t end = text.find('\n', row3);
  const size_t ux = text.rfind(',', text.rfind(',', text.rfind(',', end - 1) - 1) - 1);
  text.replace(ux, end - ux, ",0,0,0");
  try {
    trajectoryFromCsv(text, "t.csv");
    FAIL() << "a zero build direction was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.csv line 5: column 22 (ux)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spira
