// export.rapid read back with the independent reader of rapid_reader.cpp: the targets, confdata,
// external axes, arc instructions and declarations an IRC5 would run, compared with the plan and the
// solved ABB cell.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>

#include "export/export_test_data.h"
#include "export_rapid/rapid_names.h"
#include "rapid_reader.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/base/version.h"
#include "spira/kinematics/abb_confdata.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
#include "support/test_support.h"

namespace spira {
namespace {

constexpr double kMmTol = 0.01;
constexpr double kDegTol = 0.001;

RobotCell abbCell()
{
  return RobotCell(readCellFile(test::sourceDir() / "resources" / "cells" / "abb_irb1600_positioner.cell"));
}

// The plan solved on the bundled ABB cell the way the pipeline does (one configuration held).
JointTrajectory solvedOnAbb(const RobotCell& cell, const Trajectory& plan)
{
  NullProgress progress;
  return solveJointTrajectory(cell.ik(), cell.convention(), plan, cell.seededSetup(plan), progress);
}

std::vector<const test::RapidMove*> movesNamed(const test::RapidRun& run, const std::string& instruction)
{
  std::vector<const test::RapidMove*> out;
  for (const auto& m : run.moves)
    if (m.instruction == instruction) out.push_back(&m);
  return out;
}

size_t targetIndex(const std::string& name)
{
  return name.size() > 1 && name[0] == 'p' && std::isdigit(static_cast<unsigned char>(name[1]))
             ? std::stoul(name.substr(1))
             : SIZE_MAX;
}

TEST(RapidExport, PosesConfdataAndAxesMatchTheSolvedAbbCell)
{
  const RobotCell cell = abbCell();
  const Trajectory plan = test::cylinderPlan(3, 24);
  const JointTrajectory joints = solvedOnAbb(cell, plan);
  ASSERT_EQ(joints.controller, "abb_irc5");
  for (const auto& p : joints.points) ASSERT_TRUE(p.reachable);

  test::TempDir dir;
  ParamSet params;
  params.set("process_command", std::string("speed_analog"));
  const ExportResult result = test::runExporter("export.rapid", plan, &joints, params, dir.path());
  ASSERT_EQ(result.files.size(), 1u);
  EXPECT_EQ(result.files[0], dir / "spira_part.mod");
  for (const auto& w : result.warnings) ADD_FAILURE() << "warning: " << w;

  const test::RapidRun run = test::runRapid(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  // Declarations: the torch is the cell's TCP (quaternion included), the work object the identity.
  const test::RapidData& tool = run.data.at("tSpiraTorch");
  EXPECT_EQ(tool.storage, "PERS");
  EXPECT_EQ(tool.type, "tooldata");
  EXPECT_LT(test::positionError(test::rapidPose(tool.value[1]), cell.record().tool.T_flange_tcp), 1e-6);
  EXPECT_LT(test::orientationErrorDeg(test::rapidPose(tool.value[1]), cell.record().tool.T_flange_tcp), 1e-6);
  EXPECT_GT(tool.value[2][0].number, 0.0);  // a tool load must have a mass
  EXPECT_EQ(run.data.at("wobjSpira").type, "wobjdata");
  EXPECT_LT(test::positionError(test::rapidPose(run.data.at("wobjSpira").value[3]), Transform::Identity()),
            1e-12);
  EXPECT_EQ(run.data.at("smSpira").type, "seamdata");

  // One arc: MoveJ to the approach, ArcLStart at the first point, ArcL through, ArcLEnd at the last.
  ASSERT_EQ(run.moves.size(), plan.size() + 2);
  EXPECT_EQ(run.moves.front().instruction, "MoveJ");
  EXPECT_EQ(run.moves.front().args[0], "pApproach");
  EXPECT_EQ(run.moves[1].instruction, "ArcLStart");
  EXPECT_EQ(run.moves[1].args[0], "p0");
  EXPECT_EQ(run.moves[1].args[4], "fine");
  EXPECT_EQ(movesNamed(run, "ArcLStart").size(), 1u);
  EXPECT_EQ(movesNamed(run, "ArcLEnd").size(), 1u);
  EXPECT_EQ(run.moves[plan.size()].instruction, "ArcLEnd");
  EXPECT_EQ(run.moves[plan.size()].args[4], "fine");
  EXPECT_EQ(run.moves.back().instruction, "MoveL");
  EXPECT_EQ(run.moves.back().args[0], "pRetract");

  const ArmIk& ik = cell.ik();
  double worstMm = 0.0, worstDeg = 0.0;
  std::array<int, 4> firstConf{};
  for (size_t i = 0; i < plan.size(); ++i) {
    SCOPED_TRACE("p" + std::to_string(i));
    const test::RapidMove& m = run.moves[i + 1];
    ASSERT_EQ(m.args[0], "p" + std::to_string(i));
    EXPECT_EQ(m.tool, "tSpiraTorch");
    EXPECT_EQ(m.wobj, "wobjSpira");
    if (i > 1 && i + 1 < plan.size()) {
      EXPECT_EQ(m.instruction, "ArcL");
      EXPECT_EQ(m.args[4], "z1");
      EXPECT_EQ(m.args[2], "smSpira");
      // The welddata carries the move's speed (mm/s) and the WFS channel (m/min).
      const test::RapidValue& wd = run.data.at(m.args[3]).value;
      EXPECT_EQ(run.data.at(m.args[3]).type, "welddata");
      // weld_speed keeps the planned move time: the base-frame step over |part step| / TS.
      const double baseStep =
          (joints.points[i].baseTcp.translation() - joints.points[i - 1].baseTcp.translation()).norm();
      const double moveTime =
          (plan.points[i].position - plan.points[i - 1].position).norm() / plan.points[i].travelSpeed;
      EXPECT_NEAR(wd[0].number, baseStep / moveTime, 0.005 * baseStep / moveTime + 1e-3);
      // Held within the 0.05 m/min WFS resolution, written to 0.01 m/min.
      EXPECT_NEAR(wd[2][3].number, plan.points[i].wireFeed * 60.0 / 1000.0, 0.0551);
      EXPECT_NEAR(run.data.at(m.args[1]).value[0].number, wd[0].number, 1e-12);
    }
    const test::RapidData& target = run.data.at(m.args[0]);
    ASSERT_EQ(target.type, "robtarget");
    ASSERT_EQ(target.storage, "CONST");
    const Transform written = test::rapidPose(target.value);
    // The planned TCP pose, composed independently of the exporter: FK of the solved arm joints
    // times the cell's TCP.
    const JointVector q = cell.convention().fromControllerDeg(joints.points[i].robotDeg);
    const Transform planned = cell.arm().forward(q) * cell.record().tool.T_flange_tcp;
    worstMm = std::max(worstMm, test::positionError(written, planned));
    worstDeg = std::max(worstDeg, test::orientationErrorDeg(written, planned));
    // Quaternion: scalar first, normalised as written.
    const test::RapidValue& quat = target.value[1];
    double norm = 0.0;
    for (size_t k = 0; k < 4; ++k) norm += quat[k].number * quat[k].number;
    EXPECT_NEAR(std::sqrt(norm), 1.0, 1e-7);
    EXPECT_GE(quat[0].number, 0.0);
    // confdata: the quadrants of the solved joints and one cfx along the path.
    std::array<int, 4> conf{};
    for (size_t k = 0; k < 4; ++k) conf[k] = static_cast<int>(target.value[2][k].number);
    EXPECT_EQ(conf[0], static_cast<int>(std::floor((joints.points[i].robotDeg[0] + 1e-6) / 90.0)));
    EXPECT_EQ(conf[1], static_cast<int>(std::floor((joints.points[i].robotDeg[3] + 1e-6) / 90.0)));
    EXPECT_EQ(conf[2], static_cast<int>(std::floor((joints.points[i].robotDeg[5] + 1e-6) / 90.0)));
    if (i == 0) firstConf = conf;
    EXPECT_EQ(conf[3], firstConf[3]);
    // External axes: the positioner's E1, E2, then 9E9.
    EXPECT_NEAR(target.value[3][0].number, joints.points[i].externalDeg[0], 1e-4);
    EXPECT_NEAR(target.value[3][1].number, joints.points[i].externalDeg[1], 1e-4);
    for (size_t k = 2; k < 6; ++k) EXPECT_EQ(target.value[3][k].number, 9e9);
    // Every joint within the URDF limits: the exporter's joints, and the joints the written pose and
    // confdata name (IK of the written pose, the solution whose confdata is the written one).
    for (size_t k = 0; k < 6; ++k) {
      EXPECT_GE(q[static_cast<Eigen::Index>(k)], ik.chain().joint(k).lower);
      EXPECT_LE(q[static_cast<Eigen::Index>(k)], ik.chain().joint(k).upper);
    }
    const Transform writtenTip = written * cell.record().tool.T_flange_tcp.inverse();
    bool named = false;
    for (const IkSolution& s : ik.solveAll(writtenTip)) {
      if (!s.withinLimits || abbConfData(ik.model(), s.q).values != conf) continue;
      named = true;
      EXPECT_LT(test::positionError(cell.arm().forward(s.q) * cell.record().tool.T_flange_tcp, written),
                1e-6);
      for (size_t k = 0; k < 6; ++k) {
        EXPECT_GE(s.q[static_cast<Eigen::Index>(k)], ik.chain().joint(k).lower);
        EXPECT_LE(s.q[static_cast<Eigen::Index>(k)], ik.chain().joint(k).upper);
      }
      EXPECT_LT((s.q - q).cwiseAbs().maxCoeff(), degToRad(0.01));
    }
    EXPECT_TRUE(named) << "no in-limit joint vector has the written confdata";
  }
  EXPECT_LT(worstMm, kMmTol);
  EXPECT_LT(worstDeg, kDegTol);
  std::cout << "RAPID pose error vs FK of the solved joints: " << worstMm << " mm, " << worstDeg
            << " deg over " << plan.size() << " points\n";
}

// The synthetic turntable turns 5 degrees per point: an endless axis, as in the bundled cells.
JointTrajectory endlessTable(JointTrajectory joints)
{
  joints.externalLimits[1].minDeg = -1e6;
  joints.externalLimits[1].maxDeg = 1e6;
  joints.externalLimits[1].maxSpeedDegPerS = 1e6;
  return joints;
}

// Two helices one above the other as two sub-paths (a multi-branch plan).
Trajectory twoBranchPlan()
{
  Trajectory a = test::cylinderPlan(2, 12);
  Trajectory b = test::cylinderPlan(2, 12);
  for (auto& p : b.points) {
    p.position.z() += 30.0;
    p.path = 1;
  }
  for (const auto& p : b.points) a.points.push_back(p);
  for (auto& [name, channel] : a.extra) channel.resize(a.size(), channel.empty() ? 0.0 : channel.back());
  return a;
}

TEST(RapidExport, OneArcStartAndEndPerSubPathWithJointTravelBetween)
{
  const Trajectory plan = twoBranchPlan();
  const JointTrajectory joints = test::syntheticJoints(plan, "abb_irc5", true);
  test::TempDir dir;
  test::runExporter("export.rapid", plan, &joints, ParamSet(), dir.path());
  const test::RapidRun run = test::runRapid(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  const auto starts = movesNamed(run, "ArcLStart"), ends = movesNamed(run, "ArcLEnd");
  ASSERT_EQ(starts.size(), 2u);
  ASSERT_EQ(ends.size(), 2u);
  // Arc instructions alternate start, end, start, end, and no ArcL runs outside an arc.
  bool inArc = false;
  size_t travel = 0;
  for (const auto& m : run.moves) {
    if (m.instruction == "ArcLStart") {
      EXPECT_FALSE(inArc);
      inArc = true;
    } else if (m.instruction == "ArcLEnd") {
      EXPECT_TRUE(inArc);
      inArc = false;
    } else if (m.instruction == "ArcL") {
      EXPECT_TRUE(inArc);
    } else {
      EXPECT_FALSE(inArc) << m.instruction << " " << m.args[0] << " while the arc burns";
      if (m.instruction == "MoveJ" && targetIndex(m.args[0]) != SIZE_MAX) {
        ++travel;
        EXPECT_EQ(plan.points[targetIndex(m.args[0])].path, 1);
      }
    }
  }
  EXPECT_FALSE(inArc);
  EXPECT_EQ(travel, 1u);
}

TEST(RapidExport, LongPathsSplitIntoCalledModulesWithAProgramFile)
{
  const Trajectory plan = test::cylinderPlan(10, 24);  // 241 points
  const JointTrajectory joints = endlessTable(test::syntheticJoints(plan, "abb_irc5", true));
  test::TempDir dir;
  ParamSet params;
  params.set("max_points", std::int64_t{100});
  const ExportResult result = test::runExporter("export.rapid", plan, &joints, params, dir.path());
  ASSERT_EQ(result.files.size(), 5u);  // main, 3 parts, .pgf
  EXPECT_EQ(result.files.back().filename(), "spira_part.pgf");
  const std::string pgf = test::readBytes(dir / "spira_part.pgf");
  for (const char* m : {"spira_part.mod", "spira_part_001.mod", "spira_part_002.mod", "spira_part_003.mod"})
    EXPECT_NE(pgf.find(std::string("<Module>") + m + "</Module>"), std::string::npos) << m;
  const test::RapidRun run = test::runRapid(dir.path(), "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  EXPECT_EQ(run.modules.size(), 4u);
  // Every point once, in order, and one arc across the modules.
  size_t next = 0;
  for (const auto& m : run.moves) {
    const size_t i = targetIndex(m.args[0]);
    if (i == SIZE_MAX) continue;
    EXPECT_EQ(i, next++);
  }
  EXPECT_EQ(next, plan.size());
  EXPECT_EQ(movesNamed(run, "ArcLStart").size(), 1u);
  EXPECT_EQ(movesNamed(run, "ArcLEnd").size(), 1u);
  for (size_t i = 0; i < plan.size(); ++i)
    EXPECT_LT(test::positionError(test::rapidPose(run.data.at("p" + std::to_string(i)).value),
                                  joints.points[i].baseTcp),
              kMmTol);
}

TEST(RapidExport, BadNamesAreFixedOrRefused)
{
  EXPECT_TRUE(isRapidIdentifier("spira_part"));
  EXPECT_FALSE(isRapidIdentifier("1part"));
  EXPECT_FALSE(isRapidIdentifier("ENDPROC"));
  EXPECT_FALSE(isRapidIdentifier(std::string(33, 'a')));
  EXPECT_EQ(rapidModuleName("2 part-A"), "P2_part_A");
  EXPECT_EQ(rapidModuleName("module"), "module_PRG");
  EXPECT_EQ(rapidModuleName(std::string(40, 'b')).size(), 32u);
  EXPECT_FALSE(rapidDataNameProblem("tool0").empty());
  EXPECT_FALSE(rapidDataNameProblem("v100").empty());
  EXPECT_FALSE(rapidDataNameProblem("p12").empty());
  EXPECT_FALSE(rapidDataNameProblem("IF").empty());
  EXPECT_TRUE(rapidDataNameProblem("tMyTorch").empty());

  const Trajectory plan = test::cylinderPlan(1, 12);
  const JointTrajectory joints = test::syntheticJoints(plan, "abb_irc5", false);
  {
    test::TempDir dir;
    ParamSet params;
    params.set("program_name", std::string("3rd wall"));
    const ExportResult r = test::runExporter("export.rapid", plan, &joints, params, dir.path());
    ASSERT_EQ(r.files.size(), 1u);
    EXPECT_EQ(r.files[0].filename(), "P3rd_wall.mod");
    bool told = false;
    for (const auto& w : r.warnings) told = told || w.find("written as 'P3rd_wall'") != std::string::npos;
    EXPECT_TRUE(told);
    const test::RapidRun run = test::runRapid(dir.path(), "P3rd_wall");
    for (const auto& p : run.problems) ADD_FAILURE() << p;
  }
  const auto refused = [&](const std::string& key, const std::string& value, const std::string& why) {
    test::TempDir dir;
    ParamSet params;
    params.set(key, value);
    try {
      test::runExporter("export.rapid", plan, &joints, params, dir.path());
      ADD_FAILURE() << key << " '" << value << "' was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
      EXPECT_FALSE(e.hint().empty());
    }
    EXPECT_TRUE(test::filesIn(dir.path()).empty());
  };
  refused("tool_name", "PROC", "reserved word");
  refused("tool_name", "tool0", "already uses");
  refused("wobj_name", "9wobj", "does not start with a letter");
  refused("seam_name", "seam-1", "holds '-'");
  refused("weld_prefix", std::string(30, 'w'), "no room");
  refused("seam_name", "tSpiraTorch", "given to two things");
  {
    test::TempDir dir;
    ParamSet params;
    params.set("zone", std::int64_t{3});
    EXPECT_THROW(test::runExporter("export.rapid", plan, &joints, params, dir.path()), InputError);
  }
}

std::string withoutVersion(std::string text)
{
  const std::string version = kVersion;
  for (size_t at = text.find(version); at != std::string::npos; at = text.find(version, at))
    text.replace(at, version.size(), "@VERSION@");
  return text;
}

// The complete module for the golden-file plan of tests/export/golden_test.cpp (3 revolutions of 8
// points, synthetic joints with a positioner, wire feed in the welddata), reviewed line by line when
// it was made. Regenerate with SPIRA_UPDATE_GOLDEN=1 after a deliberate change and review the diff.
TEST(RapidExport, GoldenSmallCylinder)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(3, 8);
  JointTrajectory joints = test::syntheticJoints(plan, "abb_irc5", true);
  for (size_t i = 0; i < joints.size(); ++i) joints.points[i].abbConf = {-1, 0, 1, 1};
  joints.flangeTcp.translation() = Vec3(0, 0, 350);
  ParamSet params;
  params.set("program_name", std::string("small_cylinder"));
  params.set("process_command", std::string("speed_analog"));
  params.set("wfs_deadband", 0.1);
  const ExportResult result = test::runExporter("export.rapid", plan, &joints, params, dir.path());
  ASSERT_EQ(result.files.size(), 1u);
  const std::filesystem::path golden =
      test::sourceDir() / "tests" / "export" / "golden" / "small_cylinder.mod";
  const std::string got = withoutVersion(test::readBytes(result.files[0]));
  if (std::getenv("SPIRA_UPDATE_GOLDEN")) test::writeBytes(golden, got);
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden;
  EXPECT_EQ(got, test::readBytes(golden));
}

// The 100,000-point export the issue asks to stay under a second (run time printed; the bound is
// checked loosely here since the test machines are shared, and recorded in docs).
TEST(RapidExport, HundredThousandPointsExportQuickly)
{
  const Trajectory plan = test::cylinderPlan(1000, 100);
  ASSERT_GE(plan.size(), 100000u);
  JointTrajectory joints = endlessTable(test::syntheticJoints(plan, "abb_irc5", true));
  // The made-up joints drift with the point index; only the writing is timed here.
  for (AxisLimit& l : joints.robotLimits) {
    l.minDeg = -1e6;
    l.maxDeg = 1e6;
    l.maxSpeedDegPerS = 1e6;
  }
  for (AxisLimit& l : joints.externalLimits) {
    l.minDeg = -1e6;
    l.maxDeg = 1e6;
    l.maxSpeedDegPerS = 1e6;
  }
  test::TempDir dir;
  const auto start = std::chrono::steady_clock::now();
  const ExportResult result = test::runExporter("export.rapid", plan, &joints, ParamSet(), dir.path());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "RAPID export of " << plan.size() << " points: " << seconds << " s, " << result.files.size()
            << " files\n";
  EXPECT_EQ(result.files.size(), 22u);  // main + 20 parts of 5000 + .pgf
  EXPECT_LT(seconds, 5.0);
}

}  // namespace
}  // namespace spira
