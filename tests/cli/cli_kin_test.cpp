#include <gtest/gtest.h>

#include <sstream>

#include "cli_runner.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

std::string cell(const char* name)
{
  return (sourceDir() / "resources" / "cells" / name).string();
}

// Numbers following `label` on the first line that starts with `prefix`.
std::vector<double> numbersAfter(const std::string& text, const std::string& prefix)
{
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) != 0) continue;
    std::vector<double> v;
    std::istringstream words(line.substr(prefix.size()));
    for (std::string w; words >> w;) {
      try {
        size_t used = 0;
        const double x = std::stod(w, &used);
        if (used == w.size()) v.push_back(x);
      } catch (const std::exception&) {
      }
    }
    return v;
  }
  return {};
}

TEST(CliKin, KukaHomeFlangeMatchesTheReadme)
{
  const CliRun r = runCli({"kin", cell("kuka_kr16_2_table.cell"), "--fk", "0", "-90", "90", "0", "0", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // robots/README.md: HOME puts the flange at (1088, 0, 1320), $POS_ACT A 0 B 90 C 0.
  const auto flange = numbersAfter(r.out, "flange:");
  ASSERT_EQ(flange.size(), 6u) << r.out;
  EXPECT_NEAR(flange[0], 1088.0, 1e-3);
  EXPECT_NEAR(flange[1], 0.0, 1e-3);
  EXPECT_NEAR(flange[2], 1320.0, 1e-3);
  EXPECT_NEAR(flange[4], 90.0, 1e-3);
  // The TCP is 350 mm out of the flange (tool0 z, forward at HOME).
  const auto tcp = numbersAfter(r.out, "tcp");
  ASSERT_EQ(tcp.size(), 6u);
  EXPECT_NEAR(tcp[0], 1438.0, 1e-3);
}

TEST(CliKin, FanucZeroPoseFlangeMatchesTheReadme)
{
  const CliRun r = runCli({"kin", cell("fanuc_m20ia_positioner.cell"), "--fk", "0", "0", "0", "0", "0", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto flange = numbersAfter(r.out, "flange:");
  ASSERT_EQ(flange.size(), 6u) << r.out;
  EXPECT_NEAR(flange[0], 1085.0, 1e-3);
  EXPECT_NEAR(flange[2], 1040.0, 1e-3);
  EXPECT_NEAR(flange[4], -90.0, 1e-3);  // P
  EXPECT_NE(r.out.find("CONFIG 'F U T, 0, 0, 0'"), std::string::npos) << r.out;
}

// FK of a pose, then IK of the TCP it printed: one solution is the pose we started from.
TEST(CliKin, InverseOfTheForwardPoseContainsTheJoints)
{
  for (const char* c : {"kuka_kr16_2_table.cell", "fanuc_m20ia_positioner.cell"}) {
    const std::vector<std::string> q{"12.5", "-70", "95", "30", "-40", "60"};
    std::vector<std::string> args{"kin", cell(c), "--fk"};
    args.insert(args.end(), q.begin(), q.end());
    const CliRun fk = runCli(args);
    ASSERT_EQ(fk.exitCode, 0) << fk.err;
    const auto tcp = numbersAfter(fk.out, "tcp");
    ASSERT_EQ(tcp.size(), 6u);
    std::vector<std::string> ikArgs{"kin", cell(c), "--ik"};
    for (double x : tcp) {
      std::ostringstream s;
      s.precision(17);
      s << x;
      ikArgs.push_back(s.str());
    }
    const CliRun ik = runCli(ikArgs);
    ASSERT_EQ(ik.exitCode, 0) << ik.err << ik.out;
    bool found = false;
    std::istringstream in(ik.out);
    for (std::string line; std::getline(in, line);) {
      const auto colon = line.find(':');
      if (colon == std::string::npos || line.find("  ok") != 0) continue;
      const auto v = numbersAfter(line.substr(colon + 1), "");
      if (v.size() < 6) continue;
      bool same = true;
      for (size_t k = 0; k < 6; ++k) same = same && std::abs(v[k] - std::stod(q[k])) < 2e-4;
      found = found || same;
    }
    EXPECT_TRUE(found) << c << "\n" << ik.out;
  }
}

TEST(CliKin, BadArgumentsAreUsageErrors)
{
  EXPECT_EQ(runCli({"kin", cell("kuka_kr16_2_table.cell"), "--fk", "1", "2"}).exitCode, 2);
  EXPECT_EQ(runCli({"kin", cell("kuka_kr16_2_table.cell"), "--fk", "a", "0", "0", "0", "0", "0"}).exitCode,
            2);
  EXPECT_EQ(runCli({"kin", cell("kuka_kr16_2_table.cell"), "0", "0", "0", "0", "0", "0"}).exitCode, 2);
  const CliRun missing = runCli({"kin", "/nonexistent.cell", "--fk", "0", "0", "0", "0", "0", "0"});
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_NE(missing.err.find("nonexistent"), std::string::npos);
}

TEST(CliKin, FarPoseHasNoSolutionAndExitsFour)
{
  const CliRun r = runCli({"kin", cell("kuka_kr16_2_table.cell"), "--ik", "5000", "0", "0", "0", "90", "0"});
  EXPECT_EQ(r.exitCode, 4) << r.out;
  EXPECT_NE(r.out.find("out of the robot's reach"), std::string::npos);
}

}  // namespace
}  // namespace spira::test
