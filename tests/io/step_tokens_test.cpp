#include <gtest/gtest.h>

#include <string>

#include "spira/base/error.h"
#include "spira/io/step_tokens.h"

namespace spira::test {
namespace {

std::string refusal(const std::string& text, size_t limit)
{
  try {
    checkStepTokens(text, "p.step", limit);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(StepTokens, TokensUpToTheLimitPass)
{
  const std::string file = "ISO-10303-21;\nDATA;\n#1=PRODUCT('bracket','',/* a note */'',());\nENDSEC;\n";
  EXPECT_EQ(refusal(file, 12), "accepted");  // ISO-10303-21 is the longest token
  EXPECT_EQ(refusal(file, 11), "'p.step' line 1: a token of 12 characters (at most 11 are read)");
  // 'it''s a part' is 11 characters: the doubled quote stands for one.
  EXPECT_EQ(refusal("#1=PRODUCT('it''s a part');", 11), "accepted");
  EXPECT_EQ(refusal("#1=PRODUCT('it''s a part');", 10),
            "'p.step' line 1: a token of 11 characters (at most 10 are read)");
}

TEST(StepTokens, LongBareTokenAndStringAreNamedWithTheirLine)
{
  EXPECT_EQ(refusal("DATA;\n\n#5=CARTESIAN_POINT('',(" + std::string(50, '1') + ",0.,0.));", 40),
            "\'p.step\' line 3: a token of 50 characters (at most 40 are read)");
  EXPECT_EQ(refusal("DATA;\n#5=X('" + std::string(30, 'a') + "\n" + std::string(30, 'b') + "');", 50),
            "\'p.step\' line 2: a token of 61 characters (at most 50 are read)");
}

TEST(StepTokens, UnendedStringOrCommentIsRefused)
{
  EXPECT_EQ(refusal("DATA;\n#1=X('abc);\n", 100), "\'p.step\' line 2: a quoted string that never ends");
  EXPECT_EQ(refusal("DATA;\n/* half\n", 100), "\'p.step\' line 2: a comment (/*) that never ends");
  // Comments do not count as tokens, and their lines are counted.
  EXPECT_EQ(refusal("/*\n" + std::string(500, 'c') + "\n*/\n#1=X(" + std::string(60, 'z') + ");", 50),
            "\'p.step\' line 4: a token of 60 characters (at most 50 are read)");
}

}  // namespace
}  // namespace spira::test
