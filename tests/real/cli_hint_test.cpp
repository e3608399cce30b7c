#include <gtest/gtest.h>

#include "real/cli_hint.h"

namespace spira::test::real {
namespace {

TEST(CliHint, ParenthesisedHintOpeningWithAVerbCounts)
{
  const std::string err =
      "spira-cli: the part has 8 separate pieces (import one thin-walled part at a time)\n";
  ASSERT_TRUE(hasActionableHint(err));
  EXPECT_EQ(actionableHints(err).front(), "import one thin-walled part at a time");
}

TEST(CliHint, AnyOfSeveralActionsCounts)
{
  EXPECT_TRUE(hasActionableHint("spira-cli: the window is empty (the defaults are off; widen the window)\n"));
}

TEST(CliHint, CountsAndExplanationsAreNotHints)
{
  EXPECT_FALSE(
      hasActionableHint("INFEASIBLE: 12 deposit(s) outside the window, 0 process-limit violation(s)\n"));
  EXPECT_FALSE(hasActionableHint("spira-cli: internal error: boom (please report this)\n"));
  EXPECT_FALSE(hasActionableHint("spira-cli: the part cannot be planned (it has no free edge)\n"));
}

TEST(CliHint, HintLinesCount)
{
  EXPECT_TRUE(hasActionableHint("warning: x\nhint: set --h-max to 2.6\n"));
  EXPECT_TRUE(hasActionableHint("try --strategy isovalue\n"));
  EXPECT_TRUE(hasActionableHint("advice: widen the process window to 1.05 .. 3.6 mm (--h-min 1.05)\n"));
}

TEST(CliHint, MentionsIsCaseInsensitive)
{
  EXPECT_TRUE(mentionsAny("The part is a closed SOLID", {"solid"}));
  EXPECT_FALSE(mentionsAny("fill holes", {"solid", "surface"}));
}

}  // namespace
}  // namespace spira::test::real
