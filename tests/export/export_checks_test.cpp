// What both exporters must refuse or flag, and how they fail: unreachable, colliding and
// out-of-limit points (refused unless forced, then commented), unusable plans, unwritable
// folders, all-or-nothing writing and cancellation.
#include <gtest/gtest.h>

#include "spira/base/output_set.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "builtin_plugins.h"
#include "export_test_data.h"
#include "krl_reader.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/plugin/plugin_registry.h"
#include "support/test_support.h"
#include "tp_reader.h"

namespace spira {
namespace {

struct Case {
  std::string id;
  std::string controller;
  std::string mainName;
};

void PrintTo(const Case& c, std::ostream* os)
{
  *os << c.id;
}

const Case kKrl{"export.krl", "kuka_krc4", "spira_part"};
const Case kTp{"export.fanuc_tp", "fanuc_r30ib", "SPIRA_PART"};

class ExportChecks : public testing::TestWithParam<Case> {};

// Comments before the move to each plan point, and the point after which the arc is struck and
// put out, as read back from the written program.
struct ReadBack {
  std::vector<std::vector<std::string>> comments;
  size_t arcOnAt = SIZE_MAX;
  size_t arcOffAt = SIZE_MAX;
  size_t arcOns = 0;
  size_t arcOffs = 0;
};

ReadBack readBack(const Case& c, const std::filesystem::path& dir, size_t points)
{
  ReadBack r;
  r.comments.resize(points);
  if (c.id == kKrl.id) {
    const test::KrlRun run = test::runKrl(dir, c.mainName);
    for (const auto& p : run.problems) ADD_FAILURE() << p;
    for (const auto& m : run.moves) {
      if (m.target.rfind("XP", 0) != 0) continue;
      const size_t i = std::stoul(m.target.substr(2));
      r.comments[i] = m.comments;
      for (const auto& t : m.triggers) {
        if (t.find("]=TRUE") != std::string::npos) {
          ++r.arcOns;
          r.arcOnAt = i - 1;  // DISTANCE=0: where the move to XP<i> starts
        }
        if (t.find("]=FALSE") != std::string::npos) {
          ++r.arcOffs;
          r.arcOffAt = i;  // DISTANCE=1: where it ends
        }
      }
    }
  } else {
    const test::TpRun run = test::runTp(dir, c.mainName);
    for (const auto& p : run.problems) ADD_FAILURE() << p;
    for (size_t i = 0; i < points; ++i) r.comments[i] = run.moves[i + 1].comments;
    r.arcOns = run.arcStartAfter.size();
    r.arcOffs = run.arcEndAfter.size();
    if (r.arcOns) r.arcOnAt = run.arcStartAfter[0] - 1;
    if (r.arcOffs) r.arcOffAt = run.arcEndAfter[0] - 1;
  }
  return r;
}

bool mentions(const std::vector<std::string>& lines, const std::string& text)
{
  std::string all;
  for (const auto& l : lines) all += l + " ";
  return all.find(text) != std::string::npos;
}

TEST_P(ExportChecks, UnexecutablePointsAreRefusedUnlessForced)
{
  const Case& c = GetParam();
  const Trajectory plan = test::cylinderPlan();
  JointTrajectory joints = test::syntheticJoints(plan, c.controller, false);
  joints.points[5].reachable = false;
  joints.points[9].collision = true;
  joints.points[12].robotDeg[4] = 500.0;  // limits are +-400
  test::TempDir refused;
  try {
    test::runExporter(c.id, plan, &joints, ParamSet(), refused.path());
    ADD_FAILURE() << "export was not refused";
  } catch (const InfeasibleError& e) {
    EXPECT_NE(std::string(e.what()).find("3 of 37 points"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("point 5 unreachable"), std::string::npos) << e.what();
    EXPECT_NE(e.hint().find("force"), std::string::npos);
  }
  EXPECT_TRUE(test::filesIn(refused.path()).empty());

  test::TempDir forced;
  ParamSet params;
  params.set("force", true);
  const ExportResult result = test::runExporter(c.id, plan, &joints, params, forced.path());
  ASSERT_FALSE(result.files.empty());
  bool summarised = false;
  for (const auto& w : result.warnings) summarised = summarised || w.find("forced export: 3 of 37") == 0;
  EXPECT_TRUE(summarised);
  const ReadBack r = readBack(c, forced.path(), plan.size());
  const std::string marker = c.id == kKrl.id ? "WARNING" : "FORCED";
  for (size_t i = 0; i < plan.size(); ++i) {
    const bool flagged = i == 5 || i == 9 || i == 12;
    EXPECT_EQ(mentions(r.comments[i], marker), flagged) << i;
  }
  EXPECT_TRUE(mentions(r.comments[5], "unreachable"));
  EXPECT_TRUE(mentions(r.comments[9], "in collision"));
  EXPECT_TRUE(mentions(r.comments[12], "5 outside its limits"));
}

TEST_P(ExportChecks, ArcIsStruckOnceAtTheFirstDepositionPoint)
{
  const Case& c = GetParam();
  Trajectory plan = test::cylinderPlan();
  plan.points[0].arcOn = plan.points[1].arcOn = false;  // travel to the start
  plan.points[20].arcOn = false;                        // a gap the program bridges
  plan.points.back().arcOn = false;
  const JointTrajectory joints = test::syntheticJoints(plan, c.controller, false);
  test::TempDir dir;
  const ExportResult result = test::runExporter(c.id, plan, &joints, ParamSet(), dir.path());
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("off at 1 point inside"), std::string::npos) << result.warnings[0];
  const ReadBack r = readBack(c, dir.path(), plan.size());
  EXPECT_EQ(r.arcOns, 1u);
  EXPECT_EQ(r.arcOffs, 1u);
  EXPECT_EQ(r.arcOnAt, 2u);
  EXPECT_EQ(r.arcOffAt, plan.size() - 2);
}

TEST_P(ExportChecks, FastAxesAndBranchSwitchesAreWarned)
{
  const Case& c = GetParam();
  const Trajectory plan = test::cylinderPlan();
  JointTrajectory joints = test::syntheticJoints(plan, c.controller, false);
  joints.robotLimits[3].maxSpeedDegPerS = 200.0;
  joints.points[10].robotDeg[3] += 350.0;  // a jump into point 10 and back out of it
  joints.points[20].kukaStatus = 6;
  joints.points[20].fanucConfig = "F U T, 0, 0, 0";
  test::TempDir dir;
  const ExportResult result = test::runExporter(c.id, plan, &joints, ParamSet(), dir.path());
  ASSERT_EQ(result.warnings.size(), 2u);
  // Independently: the move into point 10 lasts |p10 - p9| / TS10 and turns axis 4 by |q10 - q9|.
  const double seconds =
      (plan.points[10].position - plan.points[9].position).norm() / plan.points[10].travelSpeed;
  const double rate = std::abs(joints.points[10].robotDeg[3] - joints.points[9].robotDeg[3]) / seconds;
  const std::string axis = joints.robotLimits[3].name;
  const std::string& w = result.warnings[0];
  EXPECT_EQ(w.rfind("2 moves need an axis faster than its limit (first: " + axis + " at ", 0), 0u) << w;
  const size_t at = w.find(axis + " at ") + axis.size() + 4;
  EXPECT_NEAR(std::stod(w.substr(at)), rate, 1.0) << w;
  EXPECT_NE(w.find("deg/s into point 10, limit 200 deg/s"), std::string::npos) << w;
  EXPECT_NE(result.warnings[1].find("changes 2 times (first into point 20)"), std::string::npos)
      << result.warnings[1];
}

TEST_P(ExportChecks, UnusablePlansAreInputErrors)
{
  const Case& c = GetParam();
  test::TempDir dir;
  Trajectory one = test::cylinderPlan(1, 8);
  one.points.resize(1);
  EXPECT_THROW(test::runExporter(c.id, one, nullptr, ParamSet(), dir.path()), InputError);
  Trajectory dark = test::cylinderPlan(1, 8);
  for (auto& p : dark.points) p.arcOn = false;
  EXPECT_THROW(test::runExporter(c.id, dark, nullptr, ParamSet(), dir.path()), InputError);
  Trajectory stopped = test::cylinderPlan(1, 8);
  stopped.points[3].travelSpeed = 0.0;
  EXPECT_THROW(test::runExporter(c.id, stopped, nullptr, ParamSet(), dir.path()), InputError);
  Trajectory broken = test::cylinderPlan(1, 8);
  broken.points[4].position.x() = std::nan("");
  EXPECT_THROW(test::runExporter(c.id, broken, nullptr, ParamSet(), dir.path()), InputError);
  ParamSet bad;
  bad.set("max_points", std::int64_t{3});
  EXPECT_THROW(test::runExporter(c.id, test::cylinderPlan(1, 8), nullptr, bad, dir.path()), InputError);
  EXPECT_TRUE(test::filesIn(dir.path()).empty());
}

// A name the controller would reject is fixed, the files carry the fixed name, and the user is
// told why.
TEST_P(ExportChecks, InvalidProgramNamesAreFixedWithTheReason)
{
  const Case& c = GetParam();
  test::TempDir dir;
  ParamSet params;
  params.set("program_name", std::string("3rd wall-part!"));
  const ExportResult result = test::runExporter(c.id, test::cylinderPlan(1, 8), nullptr, params, dir.path());
  const std::string fixed = c.id == kKrl.id ? "P3rd_wall_part" : "P3RD_WALL_PART";
  bool told = false;
  for (const auto& w : result.warnings)
    told = told || (w.find("'3rd wall-part!' is not a valid") != std::string::npos &&
                    w.find("written as '" + fixed + "'") != std::string::npos);
  EXPECT_TRUE(told);
  const std::vector<std::string> expected = c.id == kKrl.id
                                                ? std::vector<std::string>{fixed + ".dat", fixed + ".src"}
                                                : std::vector<std::string>{fixed + ".ls"};
  EXPECT_EQ(test::filesIn(dir.path()), expected);
  // A valid name passes without a warning.
  test::TempDir ok;
  ParamSet valid;
  valid.set("program_name", std::string(c.mainName));
  for (const auto& w : test::runExporter(c.id, test::cylinderPlan(1, 8), nullptr, valid, ok.path()).warnings)
    EXPECT_EQ(w.find("is not a valid"), std::string::npos) << w;
}

TEST_P(ExportChecks, AnUnwritableFolderFailsBeforeWriting)
{
  const Case& c = GetParam();
  test::TempDir dir;
  test::writeBytes(dir / "not_a_folder", "x");
  const Trajectory plan = test::cylinderPlan(1, 8);
  EXPECT_THROW(test::runExporter(c.id, plan, nullptr, ParamSet(), dir / "not_a_folder"), IoError);
  EXPECT_THROW(test::runExporter(c.id, plan, nullptr, ParamSet(), dir / "not_a_folder" / "sub"), IoError);
  EXPECT_EQ(test::filesIn(dir.path()), (std::vector<std::string>{"not_a_folder"}));
}

TEST_P(ExportChecks, FilesAreWrittenAllOrNone)
{
  const Case& c = GetParam();
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(3, 12);
  ParamSet params;
  params.set("max_points", std::int64_t{12});
  // A folder in the way of the second part: its rename fails after others succeeded.
  const std::string blocked = c.id == kKrl.id ? "spira_part_002.dat" : "SPIRA_PART_002.ls";
  std::filesystem::create_directories(dir / blocked / "inside");
  EXPECT_THROW(test::runExporter(c.id, plan, nullptr, params, dir.path()), IoError);
  EXPECT_TRUE(test::filesIn(dir.path()).empty());
  EXPECT_FALSE(std::filesystem::exists(dir / kOutputManifest));
}

TEST_P(ExportChecks, CancellationWritesNothing)
{
  const Case& c = GetParam();
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(3, 12);
  ExportInput input{plan, nullptr, test::testHeader()};
  CallbackProgress progress;
  progress.cancel();
  EXPECT_THROW(builtinRegistry().exporter(c.id).write(input, ParamSet(), dir.path(), progress), Cancelled);
  EXPECT_TRUE(test::filesIn(dir.path()).empty());
}

INSTANTIATE_TEST_SUITE_P(BothControllers, ExportChecks, testing::Values(kKrl, kTp),
                         [](const testing::TestParamInfo<Case>& param) {
                           return param.param.id == kKrl.id ? std::string("Krl") : std::string("FanucTp");
                         });

}  // namespace
}  // namespace spira
