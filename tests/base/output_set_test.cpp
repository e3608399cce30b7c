// Output folders replaced as whole sets (plan files, robot programs), and the check that refuses
// a folder holding a mix.
#include <gtest/gtest.h>

#include <algorithm>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/output_set.h"
#include "support/test_support.h"

namespace spira {
namespace {

namespace fs = std::filesystem;

// Every entry of `dir` (hidden ones too), sorted, sub-folders with a trailing '/'.
std::vector<std::string> entries(const fs::path& dir)
{
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string() + (e.is_directory() ? "/" : ""));
  std::sort(names.begin(), names.end());
  return names;
}

const std::vector<OutputFile> kPlan{
    {"trajectory.csv", "x,y,z\n1,2,3\n"}, {"joints.csv", "j1\n0.5\n"}, {"report.json", "{}\n"}};

TEST(OutputSet, WritesEveryFileWithAManifestTheCheckAccepts)
{
  test::TempDir tmp;
  const fs::path dir = tmp / "plan";
  fs::create_directory(dir);
  const auto written = replaceOutputSet(dir, OutputKind::Plan, kPlan);
  ASSERT_EQ(written.size(), 3u);
  EXPECT_EQ(written[2].filename(), "report.json");
  EXPECT_EQ(entries(dir),
            (std::vector<std::string>{kOutputManifest, "joints.csv", "report.json", "trajectory.csv"}));
  EXPECT_EQ(readFile(dir / "joints.csv"), "j1\n0.5\n");
  EXPECT_NO_THROW(verifyOutputSet(dir));
  // Nothing is left beside the folder.
  EXPECT_EQ(entries(tmp.path()), (std::vector<std::string>{"plan/"}));
}

// A new plan replaces the previous plan and the program made from it (a refused export then
// leaves no program of another plan beside the new one), and keeps the user's own files.
TEST(OutputSet, APlanDropsThePreviousPlanAndProgramAndKeepsOtherFiles)
{
  test::TempDir tmp;
  const fs::path dir = tmp / "plan";
  fs::create_directory(dir);
  replaceOutputSet(dir, OutputKind::Plan, kPlan);
  replaceOutputSet(dir, OutputKind::Program, {{"PART.ls", "/PROG PART\n"}});
  test::writeBytes(dir / "notes.txt", "mine");
  replaceOutputSet(dir, OutputKind::Plan, {{"trajectory.csv", "new\n"}, {"report.json", "{\"n\": 2}\n"}});
  EXPECT_EQ(entries(dir),
            (std::vector<std::string>{kOutputManifest, "notes.txt", "report.json", "trajectory.csv"}));
  EXPECT_EQ(readFile(dir / "notes.txt"), "mine");
  EXPECT_EQ(readFile(dir / "trajectory.csv"), "new\n");
  EXPECT_NO_THROW(verifyOutputSet(dir));
}

// A program replaces its own previous files (split in three parts before, in one now: no stale
// part is left) and keeps the plan and the programs of other parts exported to the same folder.
TEST(OutputSet, AProgramReplacesItsPreviousFilesAndKeepsThePlanAndOtherPrograms)
{
  test::TempDir tmp;
  const fs::path dir = tmp / "plan";
  fs::create_directory(dir);
  replaceOutputSet(dir, OutputKind::Plan, kPlan);
  replaceOutputSet(dir, OutputKind::Program, {{"b.src", "other part"}, {"b.dat", "other data"}});
  replaceOutputSet(dir, OutputKind::Program,
                   {{"a.src", "1"}, {"a.dat", "2"}, {"a_p2.src", "3"}, {"a_p3.src", "4"}});
  replaceOutputSet(dir, OutputKind::Program, {{"a.src", "one"}, {"a.dat", "two"}});
  EXPECT_EQ(entries(dir), (std::vector<std::string>{kOutputManifest, "a.dat", "a.src", "b.dat", "b.src",
                                                    "joints.csv", "report.json", "trajectory.csv"}));
  EXPECT_EQ(readFile(dir / "a.src"), "one");
  EXPECT_NO_THROW(verifyOutputSet(dir));
}

// A thermal history belongs to the plan beside it like a program: it replaces the previous history
// (5 frames then 2: no stale frame), keeps the plan and the programs, and goes with the plan. A
// re-planned plan carries its own history, which the next thermal set replaces.
TEST(OutputSet, AThermalHistoryReplacesThePreviousOneAndGoesWithThePlan)
{
  test::TempDir tmp;
  const fs::path dir = tmp / "plan";
  fs::create_directory(dir);
  replaceOutputSet(dir, OutputKind::Plan, kPlan);
  replaceOutputSet(dir, OutputKind::Program, {{"a.src", "1"}});
  replaceOutputSet(dir, OutputKind::Thermal,
                   {{"thermal.json", "{}"}, {"t_0.vtu", "0"}, {"t_1.vtu", "1"}, {"t_4.vtu", "4"}});
  replaceOutputSet(dir, OutputKind::Thermal, {{"thermal.json", "{\"n\": 2}"}, {"t_0.vtu", "zero"}});
  EXPECT_EQ(entries(dir), (std::vector<std::string>{kOutputManifest, "a.src", "joints.csv", "report.json",
                                                    "t_0.vtu", "thermal.json", "trajectory.csv"}));
  EXPECT_EQ(readFile(dir / "t_0.vtu"), "zero");
  EXPECT_NO_THROW(verifyOutputSet(dir));
  // A program exported later keeps the history.
  replaceOutputSet(dir, OutputKind::Program, {{"a.src", "2"}});
  EXPECT_TRUE(fs::exists(dir / "t_0.vtu"));

  replaceOutputSet(dir, OutputKind::Plan,
                   {{"trajectory.csv", "slower\n"},
                    {"report.json", "{}"},
                    {"thermal.json", "{}", true},
                    {"t_0.vtu", "a", true},
                    {"t_1.vtu", "b", true}});
  EXPECT_EQ(entries(dir), (std::vector<std::string>{kOutputManifest, "report.json", "t_0.vtu", "t_1.vtu",
                                                    "thermal.json", "trajectory.csv"}));
  replaceOutputSet(dir, OutputKind::Thermal, {{"thermal.json", "{}"}});
  EXPECT_EQ(entries(dir),
            (std::vector<std::string>{kOutputManifest, "report.json", "thermal.json", "trajectory.csv"}));
  EXPECT_NO_THROW(verifyOutputSet(dir));
}

// A file that cannot be written (a name longer than the file system allows) stops the set before
// anything in the folder changes.
TEST(OutputSet, AFailureLeavesThePreviousSetIntactAndNothingBeside)
{
  test::TempDir tmp;
  const fs::path dir = tmp / "plan";
  fs::create_directory(dir);
  replaceOutputSet(dir, OutputKind::Program, {{"a.src", "one"}, {"a.dat", "two"}});
  const std::vector<OutputFile> bad{{"b.src", "three"}, {std::string(300, 'x') + ".dat", "four"}};
  EXPECT_THROW(replaceOutputSet(dir, OutputKind::Program, bad), IoError);
  EXPECT_EQ(entries(dir), (std::vector<std::string>{kOutputManifest, "a.dat", "a.src"}));
  EXPECT_EQ(readFile(dir / "a.dat"), "two");
  EXPECT_NO_THROW(verifyOutputSet(dir));
  EXPECT_EQ(entries(tmp.path()), (std::vector<std::string>{"plan/"}));
}

// What a killed run leaves (a half-staged sibling folder, a temporary file inside) is removed by
// the next run and never becomes part of a set.
TEST(OutputSet, LeftoversOfAKilledRunAreRemoved)
{
  test::TempDir tmp;
  const fs::path dir = tmp / "plan";
  fs::create_directory(dir);
  fs::create_directory(tmp / ".plan.spira-stage-1234");
  test::writeBytes(tmp / ".plan.spira-stage-1234" / "trajectory.csv", "half");
  test::writeBytes(dir / ".spira-tmp-99-trajectory.csv", "half");
  replaceOutputSet(dir, OutputKind::Plan, kPlan);
  EXPECT_EQ(entries(tmp.path()), (std::vector<std::string>{"plan/"}));
  EXPECT_EQ(entries(dir),
            (std::vector<std::string>{kOutputManifest, "joints.csv", "report.json", "trajectory.csv"}));
}

// A folder that cannot be swapped as a whole (it holds a sub-folder) gets its files renamed in
// under a manifest marked incomplete until the last one: the result is the same set.
TEST(OutputSet, AFolderWithASubFolderIsReplacedInPlace)
{
  test::TempDir tmp;
  const fs::path dir = tmp / "plan";
  fs::create_directories(dir / "photos");
  replaceOutputSet(dir, OutputKind::Plan, kPlan);
  replaceOutputSet(dir, OutputKind::Plan, {{"trajectory.csv", "new\n"}, {"report.json", "{}\n"}});
  EXPECT_EQ(entries(dir),
            (std::vector<std::string>{kOutputManifest, "photos/", "report.json", "trajectory.csv"}));
  EXPECT_NO_THROW(verifyOutputSet(dir));
}

// A folder holding a file that is not the one written with the rest of its set (a run of an older
// writer killed between two renames, or a file changed by hand), or marked incomplete, is refused
// with the file named.
TEST(OutputSet, TheCheckRefusesAMixedOrIncompleteSet)
{
  test::TempDir tmp;
  const fs::path dir = tmp / "plan";
  fs::create_directory(dir);
  replaceOutputSet(dir, OutputKind::Plan, kPlan);
  test::writeBytes(dir / "trajectory.csv", "x,y,z\n1,2,4\n");  // same size, other bytes
  try {
    verifyOutputSet(dir);
    ADD_FAILURE() << "a changed file passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("trajectory.csv"), std::string::npos) << e.what();
    EXPECT_NE(e.hint().find("plan it again"), std::string::npos) << e.hint();
  }
  fs::remove(dir / "trajectory.csv");
  EXPECT_THROW(verifyOutputSet(dir), InputError);
  test::writeBytes(dir / kOutputManifest, "{\"complete\": false, \"plan\": []}\n");
  EXPECT_THROW(verifyOutputSet(dir), InputError);
  fs::remove(dir / kOutputManifest);
  EXPECT_NO_THROW(verifyOutputSet(dir));  // an older Spira's folder: nothing to check against
}

TEST(OutputSet, AMissingFolderOrARepeatedNameIsRefused)
{
  test::TempDir tmp;
  EXPECT_THROW(replaceOutputSet(tmp / "missing", OutputKind::Program, {{"a.ls", "x"}}), IoError);
  EXPECT_THROW(replaceOutputSet(tmp.path(), OutputKind::Program, {{"a.ls", "x"}, {"a.ls", "y"}}),
               InternalError);
  EXPECT_THROW(replaceOutputSet(tmp.path(), OutputKind::Program, {{kOutputManifest, "x"}}), InternalError);
}

}  // namespace
}  // namespace spira
