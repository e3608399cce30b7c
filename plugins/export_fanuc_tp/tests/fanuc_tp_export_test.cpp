// export.fanuc_tp read back with an independent parser: layout (CRLF, LINE_COUNT, numbering),
// the positions, speeds and arc instructions an R-30iB would run, compared with the plan.
#include <gtest/gtest.h>

#include <cmath>

#include "export/export_test_data.h"
#include "export/tp_reader.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/path/tool_frame.h"
#include "support/test_support.h"

namespace spira {
namespace {

constexpr double kMmTol = 0.01;
constexpr double kDegTol = 0.001;

std::vector<std::string> callsOf(const test::TpRun& run)
{
  std::vector<std::string> calls;
  for (const auto& s : run.statements)
    if (s.rfind("CALL ", 0) == 0) calls.push_back(s.substr(5));
  return calls;
}

TEST(FanucTpExport, LayoutPositionsSpeedsAndArcMatchThePlan)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan();
  const JointTrajectory joints = test::syntheticJoints(plan, "fanuc_r30ib", false);
  const ExportResult result = test::runExporter("export.fanuc_tp", plan, &joints, ParamSet(), dir.path());
  ASSERT_EQ(result.files.size(), 1u);
  EXPECT_EQ(result.files[0], dir / "SPIRA_PART.ls");
  EXPECT_TRUE(result.warnings.empty());

  const test::TpFile file = test::readTpFile(dir / "SPIRA_PART.ls");
  EXPECT_EQ(file.attributes.at("DEFAULT_GROUP"), "1,*,*,*,*");
  EXPECT_EQ(file.attributes.at("CREATE"), "DATE 24-05-01  TIME 12:30:00");
  const std::string text = test::readBytes(dir / "SPIRA_PART.ls");
  EXPECT_NE(text.find("\r\n/APPL\r\n  ARC : TRUE ;\r\n  ARC Welding Equipment : 1,*,*,*,*;\r\n/MN\r\n"),
            std::string::npos);
  EXPECT_EQ(text.rfind("/END\r\n"), text.size() - 6);
  const test::TpRun run = test::runTp(dir.path(), "SPIRA_PART");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  ASSERT_EQ(run.moves.size(), plan.size() + 2);
  EXPECT_EQ(run.moves.front().type, 'J');
  EXPECT_EQ(run.moves.front().speed, "20%");
  EXPECT_EQ(run.moves[1].speed, "20mm/sec");
  EXPECT_EQ(run.moves.back().speed, "20mm/sec");
  EXPECT_EQ(run.moves.back().termination, "FINE");
  for (size_t i = 0; i < plan.size(); ++i) {
    SCOPED_TRACE("point " + std::to_string(i));
    const test::TpMove& m = run.moves[i + 1];
    EXPECT_EQ(m.type, 'L');
    EXPECT_EQ(m.index, static_cast<int>(i + 2));
    EXPECT_FALSE(m.pos.joint);
    EXPECT_EQ(m.pos.uf, 0);
    EXPECT_EQ(m.pos.ut, 1);
    EXPECT_EQ(m.pos.config, "N U T, 0, 0, 0");  // constant, the cell's branch
    EXPECT_LT(test::positionError(test::tpPose(m.pos), joints.points[i].baseTcp), kMmTol);
    EXPECT_LT(test::orientationErrorDeg(test::tpPose(m.pos), joints.points[i].baseTcp), kDegTol);
    EXPECT_EQ(m.termination, i == 0 || i + 1 == plan.size() ? "FINE" : "CNT100");
    if (i > 0) {
      EXPECT_EQ(m.speed, std::to_string(static_cast<int>(plan.points[i].travelSpeed)) + "mm/sec");
    }
  }
  // Arc Start once, right after the move to the first point; Arc End once after the last.
  EXPECT_EQ(run.arcStartAfter, (std::vector<size_t>{1}));
  EXPECT_EQ(run.arcEndAfter, (std::vector<size_t>{plan.size()}));
  EXPECT_EQ(std::count(run.statements.begin(), run.statements.end(), "Arc Start[1]"), 1);
  EXPECT_EQ(std::count(run.statements.begin(), run.statements.end(), "Arc End[1]"), 1);
  EXPECT_EQ(std::count(run.statements.begin(), run.statements.end(), "UFRAME_NUM=0"), 1);
  EXPECT_EQ(std::count(run.statements.begin(), run.statements.end(), "UTOOL_NUM=1"), 1);
}

TEST(FanucTpExport, CommentLinesFitThePendant)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(1, 8);
  test::runExporter("export.fanuc_tp", plan, nullptr, ParamSet(), dir.path());
  const test::TpFile file = test::readTpFile(dir / "SPIRA_PART.ls");
  size_t comments = 0;
  for (const auto& l : file.lines)
    if (l.body.rfind("!", 0) == 0) {
      ++comments;
      EXPECT_LE(l.body.size(), 33u) << l.body;  // "!" + 32 characters
      EXPECT_EQ(l.body.find(';'), std::string::npos);
    }
  EXPECT_GE(comments, 8u);
  EXPECT_EQ(file.lines.front().body.rfind("!Spira ", 0), 0u);  // the comment block comes first
}

TEST(FanucTpExport, JointPositionsAreTheSolvedJoints)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(2, 12);
  const JointTrajectory joints = test::syntheticJoints(plan, "fanuc_r30ib", true);
  ParamSet params;
  params.set("position_format", std::string("joint"));
  test::runExporter("export.fanuc_tp", plan, &joints, params, dir.path());
  const test::TpRun run = test::runTp(dir.path(), "SPIRA_PART");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  ASSERT_EQ(run.moves.size(), plan.size() + 2);
  EXPECT_FALSE(run.moves.front().pos.joint);  // approach and retract stay Cartesian
  EXPECT_FALSE(run.moves.back().pos.joint);
  for (size_t i = 0; i < plan.size(); ++i) {
    const test::TpPosition& p = run.moves[i + 1].pos;
    ASSERT_TRUE(p.joint);
    for (size_t k = 0; k < 6; ++k)
      EXPECT_NEAR(p.j[k], joints.points[i].robotDeg[k], 5e-5) << i << " J" << k + 1;
    ASSERT_TRUE(p.gp2);
    EXPECT_NEAR(p.e[0], joints.points[i].externalDeg[0], 5e-5);
    EXPECT_NEAR(p.e[1], joints.points[i].externalDeg[1], 5e-5);
  }
  EXPECT_EQ(test::readTpFile(dir / "SPIRA_PART.ls").attributes.at("DEFAULT_GROUP"), "1,1,*,*,*");
}

TEST(FanucTpExport, WithoutACellTheDefaultConfigurationIsUsed)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(2, 10);
  ParamSet params;
  params.set("default_config", std::string("F D B, 0, -1, 1"));
  params.set("uframe", std::int64_t{2});
  const ExportResult result = test::runExporter("export.fanuc_tp", plan, nullptr, params, dir.path());
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("UFRAME 2"), std::string::npos);
  const test::TpRun run = test::runTp(dir.path(), "SPIRA_PART");
  for (size_t i = 0; i < plan.size(); ++i) {
    const test::TpPosition& p = run.moves[i + 1].pos;
    EXPECT_EQ(p.config, "F D B, 0, -1, 1");
    EXPECT_EQ(p.uf, 2);
    EXPECT_LT(test::positionError(test::tpPose(p), toolFrame(plan.points[i])), kMmTol);
    EXPECT_LT(test::orientationErrorDeg(test::tpPose(p), toolFrame(plan.points[i])), kDegTol);
  }
  test::TempDir bad;
  params.set("default_config", std::string("N U, 0, 0"));
  EXPECT_THROW(test::runExporter("export.fanuc_tp", plan, nullptr, params, bad.path()), InputError);
  params.set("default_config", std::string("N U T, 0, 0, 0"));
  params.set("position_format", std::string("joint"));
  EXPECT_THROW(test::runExporter("export.fanuc_tp", plan, nullptr, params, bad.path()), InputError);
  EXPECT_TRUE(test::filesIn(bad.path()).empty());
}

TEST(FanucTpExport, SpeedUnits)
{
  const Trajectory plan = test::cylinderPlan();
  const JointTrajectory joints = test::syntheticJoints(plan, "fanuc_r30ib", false);
  {
    test::TempDir dir;
    ParamSet params;
    params.set("speed_unit", std::string("cm/min"));
    test::runExporter("export.fanuc_tp", plan, &joints, params, dir.path());
    const test::TpRun run = test::runTp(dir.path(), "SPIRA_PART");
    EXPECT_EQ(run.moves[2].speed, "48cm/min");
    EXPECT_EQ(run.moves[plan.size()].speed, "60cm/min");
    EXPECT_EQ(run.moves[1].speed, "120cm/min");  // the 20 mm/s approach
  }
  {
    test::TempDir dir;
    ParamSet params;
    params.set("speed_unit", std::string("msec"));
    test::runExporter("export.fanuc_tp", plan, &joints, params, dir.path());
    const test::TpRun run = test::runTp(dir.path(), "SPIRA_PART");
    for (size_t i = 1; i < plan.size(); ++i) {
      const std::string& s = run.moves[i + 1].speed;
      ASSERT_EQ(s.substr(s.size() - 4), "msec");
      const double planned = 1000.0 * (plan.points[i].position - plan.points[i - 1].position).norm() /
                             plan.points[i].travelSpeed;
      EXPECT_NEAR(std::stod(s), planned, 0.5) << i;
    }
    EXPECT_EQ(run.moves[1].speed, "1000msec");  // 20 mm approach at 20 mm/s
  }
  {
    // Slow travel rounded to whole mm/sec is reported.
    Trajectory slow = plan;
    for (auto& p : slow.points) p.travelSpeed = 4.4;
    test::TempDir dir;
    const ExportResult r = test::runExporter("export.fanuc_tp", slow, &joints, ParamSet(), dir.path());
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("9.1 %"), std::string::npos) << r.warnings[0];
  }
  {
    // A crawl whole mm/sec cannot write (0.013 mm/s would run at 1 mm/sec, 7,592 % faster) is
    // refused, naming the unit that writes it, which then does.
    Trajectory crawl = plan;
    for (auto& p : crawl.points) p.travelSpeed = 0.013;
    test::TempDir dir;
    try {
      test::runExporter("export.fanuc_tp", crawl, &joints, ParamSet(), dir.path());
      ADD_FAILURE() << "a crawl at 0.013 mm/s was written in whole mm/sec";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("0.013 mm/s"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("7592.3 %"), std::string::npos) << e.what();
      EXPECT_NE(e.hint().find("--speed-unit msec"), std::string::npos) << e.hint();
    }
    EXPECT_TRUE(test::filesIn(dir.path()).empty());
    ParamSet msec;
    msec.set("speed_unit", std::string("msec"));
    const ExportResult r = test::runExporter("export.fanuc_tp", crawl, &joints, msec, dir.path());
    EXPECT_TRUE(r.warnings.empty());
  }
}

TEST(FanucTpExport, WireFeedRidesOnThePreviousMove)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan();
  const JointTrajectory joints = test::syntheticJoints(plan, "fanuc_r30ib", false);
  ParamSet params;
  params.set("process_command", std::string("speed_analog"));
  params.set("wfs_output", std::int64_t{2});
  params.set("wfs_gain", 1000.0);
  params.set("wfs_offset", 50.0);
  params.set("wfs_deadband", 0.2);
  test::runExporter("export.fanuc_tp", plan, &joints, params, dir.path());
  const test::TpRun run = test::runTp(dir.path(), "SPIRA_PART");
  std::vector<std::pair<size_t, long long>> expected;
  double last = 0.0;
  for (size_t i = 1; i < plan.size(); ++i) {
    const double wfs = plan.points[i].wireFeed * 60.0 / 1000.0;
    if (expected.empty() || std::abs(wfs - last) >= 0.2 - 1e-12) {
      expected.emplace_back(i, std::llround(50.0 + 1000.0 * wfs));
      last = wfs;
    }
  }
  std::vector<std::pair<size_t, long long>> written;
  for (size_t m = 0; m < run.moves.size(); ++m) {
    const std::string& o = run.moves[m].options;
    if (o.empty()) continue;
    ASSERT_EQ(o.rfind("TA 0.00sec,AO[2]=", 0), 0u) << o;
    // Move m is the move to point m - 1; its point logic fires there, as move m + 1 (point m) starts.
    written.emplace_back(m, std::stoll(o.substr(17)));
  }
  EXPECT_EQ(written, expected);
}

TEST(FanucTpExport, LongPathsAreSplitIntoPartsCalledInOrder)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(5, 12);  // 61 points
  const JointTrajectory joints = test::syntheticJoints(plan, "fanuc_r30ib", true);
  ParamSet params;
  params.set("max_points", std::int64_t{20});
  params.set("program_name", std::string("tube-3"));
  params.set("weld_schedule", std::int64_t{7});
  params.set("end_schedule", std::int64_t{8});
  const ExportResult result = test::runExporter("export.fanuc_tp", plan, &joints, params, dir.path());
  ASSERT_EQ(result.files.size(), 4u);
  EXPECT_EQ(result.files[0].filename(), "TUBE_3.ls");
  EXPECT_EQ(result.files[3].filename(), "TUBE_3_003.ls");
  const test::TpRun run = test::runTp(dir.path(), "TUBE_3");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  EXPECT_EQ(callsOf(run), (std::vector<std::string>{"TUBE_3_001", "TUBE_3_002", "TUBE_3_003"}));
  EXPECT_EQ(run.programs, (std::vector<std::string>{"TUBE_3", "TUBE_3_001", "TUBE_3_002", "TUBE_3_003"}));
  ASSERT_EQ(run.moves.size(), plan.size() + 2);
  for (size_t i = 0; i < plan.size(); ++i) {
    const test::TpMove& m = run.moves[i + 1];
    EXPECT_LT(test::positionError(test::tpPose(m.pos), joints.points[i].baseTcp), kMmTol) << i;
    EXPECT_NEAR(m.pos.e[1], joints.points[i].externalDeg[1], 5e-5);
  }
  for (const auto& name : run.programs) {
    const test::TpFile f = test::readTpFile(dir / (name + ".ls"));
    EXPECT_LE(f.positions.size(), 20u) << name;
    EXPECT_EQ(f.attributes.at("DEFAULT_GROUP"), "1,1,*,*,*");
  }
  EXPECT_EQ(run.arcStartAfter, (std::vector<size_t>{1}));
  EXPECT_EQ(run.arcEndAfter, (std::vector<size_t>{plan.size()}));
  EXPECT_EQ(std::count(run.statements.begin(), run.statements.end(), "Arc Start[7]"), 1);
  EXPECT_EQ(std::count(run.statements.begin(), run.statements.end(), "Arc End[8]"), 1);
  EXPECT_EQ(run.moves[plan.size()].program, "TUBE_3_003");
  EXPECT_EQ(run.moves.back().program, "TUBE_3");
}

TEST(FanucTpExport, GimbalLockPositionsRoundTrip)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(1, 8);
  JointTrajectory joints = test::syntheticJoints(plan, "fanuc_r30ib", false);
  for (size_t i = 0; i < joints.size(); ++i) {
    const double p = i % 2 ? kPi / 2 : -kPi / 2;
    joints.points[i].baseTcp.linear() =
        (Eigen::AngleAxisd(-0.4 * i, Vec3::UnitZ()) * Eigen::AngleAxisd(p, Vec3::UnitY()) *
         Eigen::AngleAxisd(0.25 * i, Vec3::UnitX()))
            .toRotationMatrix();
  }
  test::runExporter("export.fanuc_tp", plan, &joints, ParamSet(), dir.path());
  const test::TpRun run = test::runTp(dir.path(), "SPIRA_PART");
  for (size_t i = 0; i < plan.size(); ++i) {
    const test::TpPosition& p = run.moves[i + 1].pos;
    EXPECT_NEAR(std::abs(p.p), 90.0, 1e-9);
    EXPECT_LT(test::orientationErrorDeg(test::tpPose(p), joints.points[i].baseTcp), kDegTol) << i;
  }
}

}  // namespace
}  // namespace spira
