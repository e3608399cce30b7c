// A flag with a missing, malformed or out-of-range value is a usage error (exit 2) whatever the
// flag, with a message that names it and says what is wrong; integers are parsed strictly.
#include <gtest/gtest.h>

#include "cli_runner.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

bool has(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

// Runs 'plan' on a part that is never read: every case fails on its flags first.
CliRun planWith(const std::vector<std::string>& flags)
{
  std::vector<std::string> args{"plan", "no-such-part.stl", "-o",
                                (binaryDir() / "hostile-flags-out").string()};
  args.insert(args.end(), flags.begin(), flags.end());
  return runCli(args);
}

TEST(HostileFlags, ParameterFlagWithoutValueIsAUsageError)
{
  const CliRun r = planWith({"--h"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(has(r.err, "flag --h needs a value")) << r.err;
}

TEST(HostileFlags, NonFiniteSubstrateHeightIsAUsageError)
{
  for (const char* v : {"nan", "inf", "-inf"}) {
    const CliRun r = planWith({"--substrate-z", v});
    EXPECT_EQ(r.exitCode, 2) << v << ": " << r.err;
    EXPECT_TRUE(has(r.err, std::string("--substrate-z: '") + v + "' is not a finite number")) << r.err;
  }
}

TEST(HostileFlags, IntegersAreParsedStrictlyWithTheirRange)
{
  const CliRun loop = planWith({"--lower-loop", "1e3"});
  EXPECT_EQ(loop.exitCode, 2) << loop.err;
  EXPECT_TRUE(has(loop.err, "--lower-loop: '1e3' is not a whole number")) << loop.err;
  const CliRun negative = planWith({"--lower-loop", "-5"});
  EXPECT_EQ(negative.exitCode, 2) << negative.err;
  EXPECT_TRUE(has(negative.err, "'-5' is out of range (1 to 999999)")) << negative.err;
  const CliRun fraction = planWith({"--points-per-rev", "3.7"});
  EXPECT_EQ(fraction.exitCode, 2) << fraction.err;
  EXPECT_TRUE(has(fraction.err, "'3.7' is not a whole number (use a whole number between 8 and 20000)"))
      << fraction.err;
  const CliRun small = planWith({"--points-per-rev", "-5"});
  EXPECT_EQ(small.exitCode, 2) << small.err;
  EXPECT_TRUE(has(small.err, "between 8 and 20000")) << small.err;
}

TEST(HostileFlags, DenormalIsANumberThenRangeChecked)
{
  const CliRun r = planWith({"--h", "4.9e-324"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(has(r.err, "is out of range (use a value between 0.05 and 50 mm)")) << r.err;
  EXPECT_FALSE(has(r.err, "not a number")) << r.err;
  const CliRun huge = planWith({"--h", "1e999"});
  EXPECT_EQ(huge.exitCode, 2) << huge.err;
  EXPECT_TRUE(has(huge.err, "'1e999' is beyond the range of a double")) << huge.err;
}

TEST(HostileFlags, KinematicsNumbersAcceptADenormal)
{
  const std::string cell = (sourceDir() / "resources/cells/kuka_kr16_2_table.cell").string();
  const CliRun r = runCli({"kin", cell, "--fk", "4.9e-324", "-90", "90", "0", "0", "0"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const CliRun bad = runCli({"kin", cell, "--fk", "0", "-90", "90", "0", "0", "nan"});
  EXPECT_EQ(bad.exitCode, 2) << bad.err;
  EXPECT_TRUE(has(bad.err, "--fk: 'nan' is not a finite number")) << bad.err;
}

TEST(HostileFlags, HugeValueIsClippedInTheMessage)
{
  const CliRun r = planWith({"--points-per-rev", std::string(100000, '7') + "x"});
  EXPECT_EQ(r.exitCode, 2) << r.err.size();
  EXPECT_TRUE(has(r.err, "'" + std::string(60, '7') + "...'")) << r.err.substr(0, 300);
  EXPECT_LT(r.err.size(), 400u);
}

}  // namespace
}  // namespace spira::test
