// export.gcode read back with an independent G-code reader and put through the head's forward
// kinematics: the tool tip and torch axis of every move against the plan, the axis limits, the feeds,
// the wire feed and one arc on and off per sub-path.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "export/export_test_data.h"
#include "export_gcode/gcode_machine.h"
#include "export_gcode/head_kinematics.h"
#include "gcode_reader.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/export/export_path.h"
#include "spira/path/dwell.h"
#include "support/test_support.h"

namespace spira {
namespace {

constexpr double kMmTol = 0.01;
constexpr double kDegTol = 0.001;

std::filesystem::path machinePath()
{
  return test::sourceDir() / "resources" / "machines" / "gantry_ca_head.machine";
}

// The test cylinder with its torch leant 25 deg outwards, so that C turns with the path and A tilts.
Trajectory leaningPlan(int revolutions, int perRev)
{
  Trajectory plan = test::cylinderPlan(revolutions, perRev, 40.0, 2.0);
  const double lean = degToRad(25.0);
  for (auto& p : plan.points) p.build = (std::cos(lean) * p.build - std::sin(lean) * p.normal).normalized();
  return plan;
}

ParamSet params(double decimals = 4)
{
  ParamSet s;
  s.set("machine", machinePath().string());
  s.set("decimals", static_cast<std::int64_t>(decimals));
  s.set("program_name", std::string("leaning_cylinder"));
  return s;
}

test::GcodeRun runProgram(const std::filesystem::path& file)
{
  test::GcodeRun run = test::readGcode(test::readBytes(file), "M62 P0", "M63 P0", "M67 E0 Q", "G4 P");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  return run;
}

HeadAxes axesOf(const test::GcodeMove& m)
{
  HeadAxes a;
  a.linear = Vec3(m.axes.at('X'), m.axes.at('Y'), m.axes.at('Z'));
  a.rotaryDeg = {m.axes.at('C'), m.axes.at('A')};
  return a;
}

double angleDeg(const Vec3& a, const Vec3& b)
{
  return radToDeg(
      std::atan2(a.normalized().cross(b.normalized()).norm(), a.normalized().dot(b.normalized())));
}

TEST(GcodeExport, EveryMoveThroughTheHeadIsThePlannedToolTipAndTorchAxis)
{
  test::TempDir dir;
  const Trajectory plan = leaningPlan(4, 24);
  const ExportResult result = test::runExporter("export.gcode", plan, nullptr, params(), dir.path());
  ASSERT_EQ(result.files.size(), 1u);
  EXPECT_EQ(result.files[0], dir / "leaning_cylinder.nc");
  const GcodeMachine m = readMachineFile(machinePath());
  const test::GcodeRun run = runProgram(result.files[0]);
  // G0 to the approach, G1 into every point, G1 to the retract.
  ASSERT_EQ(run.moves.size(), plan.size() + 2);
  EXPECT_TRUE(run.moves.front().rapid);
  double worstMm = 0.0, worstDeg = 0.0;
  for (size_t i = 0; i < plan.size(); ++i) {
    SCOPED_TRACE("point " + std::to_string(i));
    const test::GcodeMove& mv = run.moves[i + 1];
    EXPECT_FALSE(mv.rapid);
    const HeadPose pose = headForward(m, axesOf(mv));
    worstMm = std::max(worstMm, (pose.tip - m.partOrigin - plan.points[i].position).norm());
    worstDeg = std::max(worstDeg, angleDeg(pose.axis, -plan.points[i].build));
    // F is the plan's travel speed in mm/min, written to 0.1.
    if (i > 0) {
      EXPECT_NEAR(mv.feed, plan.points[i].travelSpeed * 60.0, 0.05 + 1e-9);
    }
  }
  EXPECT_LT(worstMm, kMmTol);
  EXPECT_LT(worstDeg, kDegTol);
  std::printf("program through the head: worst %.3g mm, %.3g deg\n", worstMm, worstDeg);
  // The approach and retract are 20 mm back along the torch at the approach speed (20 mm/s).
  const HeadPose first = headForward(m, axesOf(run.moves.front()));
  const Vec3 back = plan.points.front().position + 20.0 * plan.points.front().build;
  EXPECT_LT((first.tip - m.partOrigin - back).norm(), kMmTol);
  EXPECT_NEAR(run.moves[1].feed, 1200.0, 1e-9);
  EXPECT_NEAR(run.moves.back().feed, 1200.0, 1e-9);

  // Every axis within its limits; C turns with the lean (four turns), never flipping.
  for (size_t k = 0; k < run.moves.size(); ++k) {
    const HeadAxes a = axesOf(run.moves[k]);
    for (size_t j = 0; j < 3; ++j) {
      EXPECT_GE(a.linear[static_cast<Eigen::Index>(j)], m.linear[j].minMm);
      EXPECT_LE(a.linear[static_cast<Eigen::Index>(j)], m.linear[j].maxMm);
    }
    for (size_t j = 0; j < 2; ++j) {
      EXPECT_GE(a.rotaryDeg[j], m.rotary[j].minDeg);
      EXPECT_LE(a.rotaryDeg[j], m.rotary[j].maxDeg);
    }
    if (k > 0) {
      EXPECT_LT(std::abs(a.rotaryDeg[0] - axesOf(run.moves[k - 1]).rotaryDeg[0]), 20.0) << k;
      EXPECT_LT(std::abs(a.rotaryDeg[1] - axesOf(run.moves[k - 1]).rotaryDeg[1]), 5.0) << k;
    }
  }
  EXPECT_GT(std::abs(run.moves[plan.size()].axes.at('C') - run.moves[1].axes.at('C')), 3.9 * 360.0);

  // One arc: on once the torch is at point 0, off once it reached the last point.
  const std::vector<std::string> expected{"move", "move", "wire feed", "arc on"};
  ASSERT_GE(run.events.size(), 4u);
  EXPECT_EQ(std::vector<std::string>(run.events.begin(), run.events.begin() + 4), expected);
  EXPECT_EQ(std::count(run.events.begin(), run.events.end(), "arc on"), 1);
  EXPECT_EQ(std::count(run.events.begin(), run.events.end(), "arc off"), 1);
  EXPECT_EQ(run.events[run.events.size() - 2], "arc off");
  for (size_t i = 1; i < plan.size(); ++i) EXPECT_TRUE(run.moves[i + 1].arcOn) << i;
  EXPECT_FALSE(run.moves.back().arcOn);
  // Wire feed in m/min: the strike's value, then within the deadband (0.05 m/min) of each point's.
  EXPECT_NEAR(run.wireFeeds.front(), plan.points.front().wireFeed * 0.06, 0.00005 + 1e-12);
  for (size_t i = 1; i < plan.size(); ++i)
    EXPECT_LE(std::abs(run.moves[i + 1].wireFeed - plan.points[i].wireFeed * 0.06), 0.05 + 0.00005) << i;
  EXPECT_GT(run.wireFeeds.size(), 10u);
  EXPECT_LT(run.wireFeeds.size(), plan.size());
}

TEST(GcodeExport, EachSubPathHasOneArcOnAndOneArcOffWithTheTravelBetweenThem)
{
  test::TempDir dir;
  Trajectory plan = leaningPlan(2, 12);
  // Two sub-paths; the second starts with two travel points (arc off).
  for (size_t i = 13; i < plan.size(); ++i) plan.points[i].path = 1;
  plan.points[13].arcOn = plan.points[14].arcOn = false;
  ParamSet p = params();
  p.set("line_numbers", true);
  const ExportResult result = test::runExporter("export.gcode", plan, nullptr, p, dir.path());
  const test::GcodeRun run = runProgram(result.files[0]);
  ASSERT_EQ(run.moves.size(), plan.size() + 2);
  std::vector<std::string> process;
  for (const auto& e : run.events)
    if (e == "arc on" || e == "arc off") process.push_back(e);
  EXPECT_EQ(process, (std::vector<std::string>{"arc on", "arc off", "arc on", "arc off"}));
  for (size_t i = 0; i < plan.size(); ++i) {
    const bool burning = (i >= 1 && i <= 12) || i >= 16;  // a move burns when it ends an arc's move
    EXPECT_EQ(run.moves[i + 1].arcOn, burning) << i;
  }
}

TEST(GcodeExport, InverseTimeFeedsAreOneOverEachMovesPlannedMinutes)
{
  test::TempDir dir;
  const Trajectory plan = leaningPlan(2, 12);
  ParamSet p = params();
  p.set("feed_mode", std::string("inverse_time"));
  const ExportResult result = test::runExporter("export.gcode", plan, nullptr, p, dir.path());
  const std::string text = test::readBytes(result.files[0]);
  EXPECT_NE(text.find("\nG21 G90 G93\n"), std::string::npos);
  size_t g1 = 0, withF = 0;
  for (size_t at = text.find("\nG1 "); at != std::string::npos; at = text.find("\nG1 ", at + 1)) {
    ++g1;
    withF += text.substr(at, text.find('\n', at + 1) - at).find(" F") != std::string::npos;
  }
  EXPECT_EQ(g1, plan.size() + 1);
  EXPECT_EQ(withF, g1);  // G93 needs F on every move
  const test::GcodeRun run = runProgram(result.files[0]);
  ASSERT_EQ(run.moves.size(), plan.size() + 2);
  // The approach: 20 mm at 20 mm/s is 1 s, F = 60 per minute.
  EXPECT_NEAR(run.moves[1].feed, 60.0, 0.0005 + 1e-9);
  for (size_t i = 1; i < plan.size(); ++i) {
    const double minutes =
        (plan.points[i].position - plan.points[i - 1].position).norm() / plan.points[i].travelSpeed / 60.0;
    EXPECT_NEAR(run.moves[i + 1].feed, 1.0 / minutes, 0.0005 + 1e-9) << i;
  }
}

TEST(GcodeExport, ADwellPutsTheArcOutWaitsAndStrikesAgain)
{
  test::TempDir dir;
  Trajectory plan = leaningPlan(2, 12);
  // Point 12 is a dwell's lift: arc off, 7.5 s wait; the arc strikes again at 13.
  plan.points[12].arcOn = false;
  plan.extra[kDwellChannel] = std::vector<double>(plan.size(), 0.0);
  plan.extra[kDwellChannel][12] = 7.5;
  const ExportResult result = test::runExporter("export.gcode", plan, nullptr, params(), dir.path());
  const test::GcodeRun run = runProgram(result.files[0]);
  ASSERT_EQ(run.dwells, std::vector<double>{7.5});
  std::vector<std::string> process;
  for (const auto& e : run.events)
    if (e != "move" && e != "wire feed") process.push_back(e);
  EXPECT_EQ(process, (std::vector<std::string>{"arc on", "arc off", "dwell", "arc on", "arc off"}));
  // The wait comes once the torch reached the lift (move 13: the approach is move 0).
  size_t moves = 0;
  for (const auto& e : run.events) {
    if (e == "dwell") break;
    moves += e == "move";
  }
  EXPECT_EQ(moves, 14u);
}

TEST(GcodeExport, ALedWireFeedIsWrittenOnTheMoveDuringWhichItIsDue)
{
  test::TempDir dir;
  Trajectory plan = leaningPlan(2, 12);
  // A command that steps by 0.5 m/min (30 mm/min) at every point, due 5 s (about two moves) ahead of it.
  std::vector<double> command(plan.size()), lead(plan.size(), 5.0);
  for (size_t i = 0; i < plan.size(); ++i) command[i] = 40.0 + 10.0 * static_cast<double>(i % 2);
  plan.extra[kWfsCommandChannel] = command;
  plan.extra[kWfsLeadChannel] = lead;
  ParamSet p = params();
  p.set("wfs_deadband", 0.0);
  const ExportResult result = test::runExporter("export.gcode", plan, nullptr, p, dir.path());
  const test::GcodeRun run = runProgram(result.files[0]);
  // Move times from the plan; point k's setpoint is due at t_k - 5 s, which lies in the move from
  // point j to j+1 with t_j <= due < t_j+1; so the value in force during that move is point k's
  // (the later of two due in one move wins).
  std::vector<double> t(plan.size(), 0.0);
  for (size_t i = 1; i < plan.size(); ++i)
    t[i] = t[i - 1] +
           (plan.points[i].position - plan.points[i - 1].position).norm() / plan.points[i].travelSpeed;
  size_t checked = 0;
  for (size_t j = 0; j + 1 < plan.size(); ++j) {
    size_t due = SIZE_MAX;
    for (size_t k = 1; k < plan.size(); ++k)
      if (t[k] - 5.0 >= t[j] && t[k] - 5.0 < t[j + 1]) due = k;
    if (due == SIZE_MAX) continue;
    EXPECT_NEAR(run.moves[j + 2].wireFeed, command[due] * 0.06, 1e-4) << "move into point " << j + 1;
    ++checked;
  }
  EXPECT_GT(checked, 10u);
  // Point 0's setpoint before the arc strikes.
  EXPECT_NEAR(run.wireFeeds.front(), command[0] * 0.06, 1e-4);
}

TEST(GcodeExport, MissingOrBadMachinesAndFastMovesAreRefused)
{
  test::TempDir dir;
  const Trajectory plan = leaningPlan(1, 12);
  ParamSet p = params();
  p.set("machine", std::string());
  EXPECT_THROW(test::runExporter("export.gcode", plan, nullptr, p, dir.path()), InputError);
  p.set("machine", (dir / "missing.machine").string());
  EXPECT_THROW(test::runExporter("export.gcode", plan, nullptr, p, dir.path()), IoError);
  Trajectory fast = plan;
  fast.points[5].travelSpeed = 150.0;  // 9000 mm/min on a 6000 mm/min machine
  try {
    test::runExporter("export.gcode", fast, nullptr, params(), dir.path());
    FAIL() << "a move above the machine's feed passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("program point 5 is planned at 9000"), std::string::npos)
        << e.what();
  }
  Trajectory steep = plan;
  steep.points[3].build = Vec3(0.0, 1.0, -0.2).normalized();  // the torch pointing up: A beyond 95 deg
  try {
    test::runExporter("export.gcode", steep, nullptr, params(), dir.path());
    FAIL() << "a torch beyond A's limits passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("program point 3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("A = "), std::string::npos) << e.what();
  }
  EXPECT_TRUE(test::filesIn(dir.path()).empty());
}

}  // namespace
}  // namespace spira
