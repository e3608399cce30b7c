#include <gtest/gtest.h>

#include <cmath>

#include "spira/base/error.h"
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
