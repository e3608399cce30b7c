// spira-cli plans the same part to the same bytes with one thread and with four: trajectory.csv,
// joints.csv, the robot program and report.json (its measured times left out).
#include <gtest/gtest.h>

#include "spira/base/output_set.h"

#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "determinism_parts.h"
#include "exact_diff.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

// The report's keys that hold measured times, not plan content.
const char* const kTimingKeys[] = {"timings_s", "kinematics_timings_s"};

nlohmann::json reportWithoutTimes(const std::filesystem::path& file)
{
  nlohmann::json report = nlohmann::json::parse(readBytes(file));
  for (const char* key : kTimingKeys) report.erase(key);
  return report;
}

// `threads` for Spira's own parallel loops, and as many for the libraries under CHOLMOD: OpenMP
// (its loops) and OpenBLAS (which Spira holds to one thread while CHOLMOD factorises). The
// program's header carries its date: both runs date it the same.
CliRun plan(const DeterminismPart& part, int threads, const std::filesystem::path& dir)
{
  const std::string n = std::to_string(threads);
  const std::vector<std::string> env = {"OMP_NUM_THREADS=" + n, "OMP_THREAD_LIMIT=" + n,
                                        "OPENBLAS_NUM_THREADS=" + n, "SOURCE_DATE_EPOCH=1700000000"};
  std::vector<std::string> args = {"plan",      (sourceDir() / part.file).string(),
                                   "-o",        dir.string(),
                                   "--threads", std::to_string(threads),
                                   "--export",  part.program};
  args.insert(args.end(), part.flags.begin(), part.flags.end());
  if (!part.cell.empty()) {
    args.push_back("--cell");
    args.push_back((sourceDir() / part.cell).string());
  }
  return runCli(args, env);
}

class ThreadCount : public ::testing::TestWithParam<DeterminismPart> {};

TEST_P(ThreadCount, OneAndFourThreadsWriteTheSameFiles)
{
  const DeterminismPart& part = GetParam();
  TempDir one, four;
  const CliRun a = plan(part, 1, one.path());
  const CliRun b = plan(part, 4, four.path());
  ASSERT_TRUE(a.exitCode == 0 || a.exitCode == 4) << a.err << a.out;
  EXPECT_EQ(a.exitCode, b.exitCode) << b.err;
  // report.json differs in its measured times, and so does its checksum in the set's manifest.
  EXPECT_EQ(folderDifference(one.path(), four.path(), {"report.json", kOutputManifest}), "");
  const nlohmann::json ra = reportWithoutTimes(one / "report.json"),
                       rb = reportWithoutTimes(four / "report.json");
  EXPECT_TRUE(ra == rb) << nlohmann::json::diff(ra, rb).dump();
  if (!part.cell.empty()) {
    EXPECT_TRUE(std::filesystem::exists(one / "joints.csv"));
  }
}

TEST(ThreadOption, TakesAWholeNumberOfThreadsAnywhereOnTheLine)
{
  EXPECT_EQ(runCli({"--threads", "2", "--version"}).exitCode, 0);
  EXPECT_EQ(runCli({"plugins", "--threads=1"}).exitCode, 0);
  for (const char* bad : {"0", "-1", "two", "1.5", "257"}) {
    const CliRun r = runCli({"--threads", bad, "plugins"});
    EXPECT_EQ(r.exitCode, 2) << bad;
    EXPECT_NE(r.err.find("whole number of threads"), std::string::npos) << r.err;
  }
  EXPECT_EQ(runCli({"plugins"}, {"SPIRA_THREADS=many"}).exitCode, 2);
}

std::string caseName(const ::testing::TestParamInfo<DeterminismPart>& param)
{
  return partName(param.param);
}

INSTANTIATE_TEST_SUITE_P(Parts, ThreadCount, ::testing::ValuesIn(determinismParts()), caseName);

}  // namespace
}  // namespace spira::test
