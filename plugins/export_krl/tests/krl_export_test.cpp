// export.krl read back with an independent parser: the targets, speeds, triggers and calls a
// KR C4 would run, compared with the plan and the solved cell.
#include <gtest/gtest.h>

#include <cmath>

#include "export/export_test_data.h"
#include "export/krl_reader.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/path/tool_frame.h"
#include "support/test_support.h"

namespace spira {
namespace {

constexpr double kMmTol = 0.01;
constexpr double kDegTol = 0.001;

size_t countTriggers(const test::KrlRun& run, const std::string& needle)
{
  size_t n = 0;
  for (const auto& m : run.moves)
    for (const auto& t : m.triggers)
      if (t.find(needle) != std::string::npos) ++n;
  return n;
}

// Index (into run.moves) of the move to XP<i>.
std::vector<size_t> pathMoves(const test::KrlRun& run, size_t count)
{
  std::vector<size_t> at(count, SIZE_MAX);
  for (size_t m = 0; m < run.moves.size(); ++m) {
    const std::string& t = run.moves[m].target;
    if (t.rfind("XP", 0) == 0) {
      const size_t i = std::stoul(t.substr(2));
      EXPECT_EQ(at[i], SIZE_MAX) << t << " visited twice";
      at[i] = m;
    }
  }
  return at;
}

TEST(KrlExport, TargetsSpeedsAndArcMatchThePlan)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan();
  const JointTrajectory joints = test::syntheticJoints(plan, "kuka_krc4", false);
  const ExportResult result = test::runExporter("export.krl", plan, &joints, ParamSet(), dir.path());
  ASSERT_EQ(result.files.size(), 2u);
  EXPECT_EQ(result.files[0], dir / "spira_part.src");
  EXPECT_EQ(result.files[1], dir / "spira_part.dat");
  EXPECT_TRUE(result.warnings.empty());

  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  ASSERT_EQ(run.moves.size(), plan.size() + 2);
  EXPECT_EQ(run.moves.front().motion, "PTP");
  EXPECT_EQ(run.moves.front().target, "XAPPROACH");
  EXPECT_EQ(run.moves.back().target, "XRETRACT");

  const auto at = pathMoves(run, plan.size());
  double lo = 1e9, hi = 0.0;
  for (const auto& p : plan.points) {
    lo = std::min(lo, p.travelSpeed);
    hi = std::max(hi, p.travelSpeed);
  }
  for (size_t i = 0; i < plan.size(); ++i) {
    SCOPED_TRACE("XP" + std::to_string(i));
    ASSERT_NE(at[i], SIZE_MAX);
    const test::KrlMove& m = run.moves[at[i]];
    EXPECT_EQ(m.motion, "LIN");
    EXPECT_LT(test::positionError(test::krlPose(m.pose), joints.points[i].baseTcp), kMmTol);
    EXPECT_LT(test::orientationErrorDeg(test::krlPose(m.pose), joints.points[i].baseTcp), kDegTol);
    EXPECT_EQ(m.pose.s, 2);  // the configuration stays the one the cell solved
    EXPECT_EQ(m.pose.t, 35);
    EXPECT_FALSE(m.pose.e1.has_value());
    EXPECT_EQ(m.approximated, i > 0 && i + 1 < plan.size());
    if (i > 0) {
      EXPECT_NEAR(m.velCp * 1000.0, plan.points[i].travelSpeed, 0.005);
      EXPECT_GE(m.velCp * 1000.0, lo - 0.005);
      EXPECT_LE(m.velCp * 1000.0, hi + 0.005);
    }
  }
  // One arc on, struck at XP0 as the move to XP1 starts; one arc off on arrival at the end.
  EXPECT_EQ(countTriggers(run, "]=TRUE"), 1u);
  EXPECT_EQ(countTriggers(run, "]=FALSE"), 1u);
  ASSERT_EQ(run.moves[at[1]].triggers.size(), 1u);
  EXPECT_EQ(run.moves[at[1]].triggers[0].rfind("TRIGGER WHEN DISTANCE=0 DELAY=0 DO $OUT[1]=TRUE", 0), 0u);
  ASSERT_EQ(run.moves[at[plan.size() - 1]].triggers.size(), 1u);
  EXPECT_EQ(
      run.moves[at[plan.size() - 1]].triggers[0].rfind("TRIGGER WHEN DISTANCE=1 DELAY=0 DO $OUT[1]=FALSE", 0),
      0u);
  // $VEL.CP only where the speed changes: approach, 8 mm/s, 10 mm/s, retract.
  size_t velocities = 0;
  for (const auto& s : run.statements) velocities += s.rfind("$VEL.CP=", 0) == 0;
  EXPECT_EQ(velocities, 4u);
  EXPECT_NEAR(run.moves.back().velCp, 0.02, 1e-12);
}

TEST(KrlExport, ApproachAndRetractRunAlongTheTorchAxis)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(1, 12);
  const JointTrajectory joints = test::syntheticJoints(plan, "kuka_krc4", false);
  ParamSet params;
  params.set("approach_distance", 35.0);
  test::runExporter("export.krl", plan, &joints, params, dir.path());
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  ASSERT_EQ(run.moves.size(), plan.size() + 2);
  const Transform first = joints.points.front().baseTcp;
  const Transform last = joints.points.back().baseTcp;
  const Transform approach = test::krlPose(run.moves.front().pose);
  const Transform retract = test::krlPose(run.moves.back().pose);
  // 35 mm back against the torch axis z (which points from the torch to the deposit).
  EXPECT_NEAR((approach.translation() - (first.translation() - 35.0 * first.linear().col(2))).norm(), 0.0,
              kMmTol);
  EXPECT_NEAR((retract.translation() - (last.translation() - 35.0 * last.linear().col(2))).norm(), 0.0,
              kMmTol);
  EXPECT_LT(test::orientationErrorDeg(approach, first), kDegTol);
  EXPECT_EQ(run.moves.front().pose.s, 2);

  test::TempDir none;
  params.set("approach_distance", 0.0);
  test::runExporter("export.krl", plan, &joints, params, none.path());
  const test::KrlRun direct = test::runKrl(none.path(), "spira_part");
  ASSERT_EQ(direct.moves.size(), plan.size());
  EXPECT_EQ(direct.moves.front().motion, "PTP");
  EXPECT_EQ(direct.moves.front().target, "XP0");
}

TEST(KrlExport, WithoutACellTargetsAreTorchPosesInThePartFrame)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(2, 10);
  ParamSet params;
  params.set("base", std::int64_t{3});
  const ExportResult result = test::runExporter("export.krl", plan, nullptr, params, dir.path());
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("no solved cell"), std::string::npos);
  EXPECT_NE(result.warnings[0].find("BASE_DATA[3]"), std::string::npos);
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  const auto at = pathMoves(run, plan.size());
  for (size_t i = 0; i < plan.size(); ++i) {
    const test::KrlMove& m = run.moves[at[i]];
    EXPECT_LT(test::positionError(test::krlPose(m.pose), toolFrame(plan.points[i])), kMmTol);
    EXPECT_LT(test::orientationErrorDeg(test::krlPose(m.pose), toolFrame(plan.points[i])), kDegTol);
    EXPECT_FALSE(m.pose.s.has_value());
    EXPECT_FALSE(m.pose.t.has_value());
  }
  bool baseSet = false;
  for (const auto& s : run.statements) baseSet = baseSet || s == "$BASE=BASE_DATA[3]";
  EXPECT_TRUE(baseSet);
}

TEST(KrlExport, PositionerAxesAreTheSolvedValues)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(2, 12);
  const JointTrajectory joints = test::syntheticJoints(plan, "kuka_krc4", true);
  test::runExporter("export.krl", plan, &joints, ParamSet(), dir.path());
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  const auto at = pathMoves(run, plan.size());
  for (size_t i = 0; i < plan.size(); ++i) {
    const test::KrlTarget& t = run.moves[at[i]].pose;
    ASSERT_TRUE(t.e1 && t.e2);
    EXPECT_NEAR(*t.e1, joints.points[i].externalDeg[0], 5e-5);
    EXPECT_NEAR(*t.e2, joints.points[i].externalDeg[1], 5e-5);
  }
  EXPECT_NEAR(*run.moves.front().pose.e2, joints.points.front().externalDeg[1], 5e-5);
}

TEST(KrlExport, WireFeedSetpointsFollowTheDeadband)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan();
  const JointTrajectory joints = test::syntheticJoints(plan, "kuka_krc4", false);
  ParamSet params;
  params.set("process_command", std::string("speed_analog"));
  params.set("wfs_output", std::int64_t{3});
  params.set("wfs_gain", 0.2);
  params.set("wfs_offset", -0.1);
  params.set("wfs_deadband", 0.2);
  test::runExporter("export.krl", plan, &joints, params, dir.path());
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  // Expected setpoints, from the plan: move i carries WFS_i when it moved 0.2 m/min since the last.
  std::vector<std::pair<size_t, double>> expected;
  double last = 0.0;
  for (size_t i = 1; i < plan.size(); ++i) {
    const double wfs = plan.points[i].wireFeed * 60.0 / 1000.0;
    if (expected.empty() || std::abs(wfs - last) >= 0.2 - 1e-12) {
      expected.emplace_back(i, -0.1 + 0.2 * wfs);
      last = wfs;
    }
  }
  std::vector<std::pair<size_t, double>> written;
  for (const auto& m : run.moves)
    for (const auto& t : m.triggers) {
      const std::string key = "DO $ANOUT[3]=";
      const size_t k = t.find(key);
      if (k == std::string::npos) continue;
      EXPECT_EQ(t.rfind("TRIGGER WHEN DISTANCE=0 DELAY=0", 0), 0u);
      written.emplace_back(std::stoul(m.target.substr(2)), std::stod(t.substr(k + key.size())));
    }
  ASSERT_EQ(written.size(), expected.size());
  EXPECT_GT(expected.size(), 4u);
  EXPECT_LT(expected.size(), plan.size() - 1);  // the deadband dropped some
  for (size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(written[k].first, expected[k].first);
    EXPECT_NEAR(written[k].second, expected[k].second, 5e-5);
  }
  // The first setpoint is planned with the arc-on move, before the arc trigger.
  EXPECT_EQ(run.moves[2].target, "XP1");
  ASSERT_EQ(run.moves[2].triggers.size(), 2u);
  EXPECT_NE(run.moves[2].triggers[0].find("$ANOUT[3]"), std::string::npos);
  EXPECT_NE(run.moves[2].triggers[1].find("$OUT[1]=TRUE"), std::string::npos);
}

TEST(KrlExport, AnalogModeWritesOneSpeedAndRefusesValuesOutOfRange)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan();
  const JointTrajectory joints = test::syntheticJoints(plan, "kuka_krc4", false);
  ParamSet params;
  params.set("process_command", std::string("analog"));
  const ExportResult result = test::runExporter("export.krl", plan, &joints, params, dir.path());
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("varies from 8 to 10 mm/s"), std::string::npos);
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  for (const auto& m : run.moves)
    if (m.target != "XAPPROACH" && m.target != "XP0" && m.target != "XRETRACT") {
      EXPECT_NEAR(m.velCp, 0.008, 1e-12);
    }

  test::TempDir other;
  params.set("wfs_gain", 0.5);  // 3.5 m/min -> 1.75, past $ANOUT's 1.0
  EXPECT_THROW(test::runExporter("export.krl", plan, &joints, params, other.path()), InputError);
  EXPECT_TRUE(test::filesIn(other.path()).empty());
}

TEST(KrlExport, JobSelectionAndFramesAreWrittenOnce)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(1, 12);
  const JointTrajectory joints = test::syntheticJoints(plan, "kuka_krc4", false);
  ParamSet params;
  params.set("job_output", std::int64_t{17});
  params.set("weld_job", std::int64_t{42});
  params.set("end_job", std::int64_t{43});
  params.set("tool", std::int64_t{4});
  params.set("c_dis", 0.0);
  test::runExporter("export.krl", plan, &joints, params, dir.path());
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  const auto& st = run.statements;
  EXPECT_EQ(std::count(st.begin(), st.end(), "SIGNAL SPIRA_JOB $OUT[17] TO $OUT[24]"), 1);
  EXPECT_EQ(std::count(st.begin(), st.end(), "SPIRA_JOB=42"), 1);
  EXPECT_EQ(std::count(st.begin(), st.end(), "$TOOL=TOOL_DATA[4]"), 1);
  EXPECT_EQ(std::count(st.begin(), st.end(), "$BASE=$NULLFRAME"), 1);
  EXPECT_EQ(std::count(st.begin(), st.end(), "BAS(#INITMOV,0)"), 1);
  for (const auto& m : run.moves) EXPECT_FALSE(m.approximated);  // c_dis 0: exact stops
  // The end job is switched with the arc, on arrival at the last point, before the arc goes off.
  const auto& last = run.moves[plan.size()].triggers;
  ASSERT_EQ(last.size(), 2u);
  EXPECT_EQ(last[0], "TRIGGER WHEN DISTANCE=1 DELAY=0 DO SPIRA_JOB=43 ; end job at XP12");
  EXPECT_EQ(last[1].rfind("TRIGGER WHEN DISTANCE=1 DELAY=0 DO $OUT[1]=FALSE", 0), 0u);
  for (const auto& s : st) EXPECT_NE(s.rfind("$APO.CDIS", 0), 0u);
}

TEST(KrlExport, LongPathsAreSplitIntoPartsCalledInOrder)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(5, 12);  // 61 points
  const JointTrajectory joints = test::syntheticJoints(plan, "kuka_krc4", true);
  ParamSet params;
  params.set("max_points", std::int64_t{15});
  params.set("program_name", std::string("Dome test #2"));
  params.set("job_output", std::int64_t{9});
  params.set("end_job", std::int64_t{2});
  const ExportResult result = test::runExporter("export.krl", plan, &joints, params, dir.path());
  // 60 moves after XP0 in 4 parts of 15; main and parts as .src/.dat pairs.
  ASSERT_EQ(result.files.size(), 10u);
  EXPECT_EQ(result.files[0].filename(), "Dome_test_2.src");
  EXPECT_EQ(result.files[2].filename(), "Dome_test_2_001.src");
  EXPECT_EQ(result.files[9].filename(), "Dome_test_2_004.dat");
  const test::KrlRun run = test::runKrl(dir.path(), "Dome_test_2");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  EXPECT_EQ(run.programs, (std::vector<std::string>{"Dome_test_2", "Dome_test_2_001", "Dome_test_2_002",
                                                    "Dome_test_2_003", "Dome_test_2_004"}));
  // Every point once, in plan order, each equal to the cell's pose.
  ASSERT_EQ(run.moves.size(), plan.size() + 2);
  for (size_t i = 0; i < plan.size(); ++i) {
    const test::KrlMove& m = run.moves[i + 1];
    EXPECT_EQ(m.target, "XP" + std::to_string(i));
    EXPECT_LT(test::positionError(test::krlPose(m.pose), joints.points[i].baseTcp), kMmTol);
  }
  for (const auto& name : run.programs) {
    std::vector<std::string> problems;
    EXPECT_LE(test::readKrlDat(dir / (name + ".dat"), problems).size(), 15u) << name;
  }
  EXPECT_EQ(countTriggers(run, "]=TRUE"), 1u);
  EXPECT_EQ(countTriggers(run, "]=FALSE"), 1u);
  EXPECT_EQ(run.moves[2].program, "Dome_test_2_001");  // arc struck by the first part
  EXPECT_EQ(run.moves[plan.size()].program, "Dome_test_2_004");
  // The part that switches the end job declares the job signal it assigns.
  const std::string lastText = test::readBytes(dir / "Dome_test_2_004.src");
  EXPECT_NE(lastText.find("\r\nSIGNAL SPIRA_JOB $OUT[9] TO $OUT[16]\r\n"), std::string::npos);
  EXPECT_NE(lastText.find("DO SPIRA_JOB=2 ; end job at XP60"), std::string::npos);
  // The speed of the retract is set again after the parts ran at the travel speed.
  EXPECT_NEAR(run.moves.back().velCp, 0.02, 1e-12);
  EXPECT_NEAR(run.moves[plan.size()].velCp, 0.01, 1e-12);
}

TEST(KrlExport, GimbalLockTargetsRoundTrip)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(1, 8);
  JointTrajectory joints = test::syntheticJoints(plan, "kuka_krc4", false);
  for (size_t i = 0; i < joints.size(); ++i) {
    // B = +-90 with varying A and C: only A -+ C is defined there.
    const double b = i % 2 ? kPi / 2 : -kPi / 2;
    joints.points[i].baseTcp.linear() =
        (Eigen::AngleAxisd(0.3 * i, Vec3::UnitZ()) * Eigen::AngleAxisd(b, Vec3::UnitY()) *
         Eigen::AngleAxisd(-0.2 * i, Vec3::UnitX()))
            .toRotationMatrix();
  }
  test::runExporter("export.krl", plan, &joints, ParamSet(), dir.path());
  const test::KrlRun run = test::runKrl(dir.path(), "spira_part");
  const auto at = pathMoves(run, plan.size());
  for (size_t i = 0; i < plan.size(); ++i) {
    const test::KrlTarget& t = run.moves[at[i]].pose;
    EXPECT_NEAR(std::abs(t.b), 90.0, 1e-9);
    EXPECT_LT(test::orientationErrorDeg(test::krlPose(t), joints.points[i].baseTcp), kDegTol) << i;
  }
}

TEST(KrlExport, RefusesAJointTrajectoryOfAnotherController)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(1, 8);
  const JointTrajectory fanuc = test::syntheticJoints(plan, "fanuc_r30ib", false);
  EXPECT_THROW(test::runExporter("export.krl", plan, &fanuc, ParamSet(), dir.path()), InputError);
  JointTrajectory shorter = test::syntheticJoints(plan, "kuka_krc4", false);
  shorter.points.pop_back();
  EXPECT_THROW(test::runExporter("export.krl", plan, &shorter, ParamSet(), dir.path()), InputError);
  EXPECT_TRUE(test::filesIn(dir.path()).empty());
}

}  // namespace
}  // namespace spira
