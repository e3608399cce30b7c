#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "spira/base/number_text.h"

namespace spira::test {
namespace {

TEST(NumberText, FiniteNumbersAreReadWholeAndStrictly)
{
  std::string problem;
  EXPECT_EQ(parseFiniteNumber("+2.5", problem), 2.5);
  EXPECT_EQ(parseFiniteNumber("4.9e-324", problem), std::numeric_limits<double>::denorm_min());
  for (const char* bad : {"", "1,5", " 1", "1 ", "0x10", "--1"}) {
    EXPECT_FALSE(parseFiniteNumber(bad, problem)) << bad;
    EXPECT_EQ(problem, "is not a number") << bad;
  }
  EXPECT_FALSE(parseFiniteNumber("1e400", problem));
  EXPECT_EQ(problem, "is beyond the range of a double (about 1.8e308)");
  EXPECT_FALSE(parseFiniteNumber("nan", problem));
  EXPECT_EQ(problem, "is not a finite number");
  EXPECT_EQ(parseWholeNumber("-12", problem), -12);
  EXPECT_FALSE(parseWholeNumber("1e3", problem));
  EXPECT_FALSE(parseWholeNumber("3.7", problem));
}

// Mesh coordinates out of range are kept as infinities so that the import counts and places them.
TEST(NumberText, MeshNumbersTurnOverflowIntoInfinityAndUnderflowIntoZero)
{
  EXPECT_EQ(parseMeshNumber("+1.25e2"), 125.0);
  EXPECT_EQ(parseMeshNumber("1e400"), std::numeric_limits<double>::infinity());
  EXPECT_EQ(parseMeshNumber("-1e400"), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(parseMeshNumber("1e-400"), 0.0);
  EXPECT_TRUE(std::isnan(*parseMeshNumber("nan")));
  for (const char* bad : {"", "+", "1.0.0", "x", "1e", "1 "}) EXPECT_FALSE(parseMeshNumber(bad)) << bad;
}

TEST(NumberText, LongUserTextIsClipped)
{
  const std::string clipped = clippedText(std::string(100000, 'y'));
  EXPECT_LT(clipped.size(), 70u);
  EXPECT_EQ(clipped.substr(0, 10), std::string(10, 'y'));
  EXPECT_EQ(clippedText("short"), "short");
}

// The message forms: rounded to at most three decimals without trailing zeros, and %g-like
// significant digits (what mesh reports and refusals print).
TEST(NumberText, MessageNumbersAreRoundedOrSignificant)
{
  EXPECT_EQ(roundedText(1.23456, 3), "1.235");
  EXPECT_EQ(roundedText(2.0004, 3), "2");
  EXPECT_EQ(roundedText(120.0, 3), "120");
  EXPECT_EQ(roundedText(-0.0004, 3), "0");  // no "-0"
  EXPECT_EQ(roundedText(0.1, 3), "0.1");    // the shortest text, not 0.10000000000000001
  EXPECT_EQ(significantText(1234567.0, 6), "1.23457e+06");
  EXPECT_EQ(significantText(0.000123456, 4), "0.0001235");
  EXPECT_EQ(significantText(52.0, 6), "52");
  EXPECT_DOUBLE_EQ(roundedTo(2.71828, 2), 2.72);
}

}  // namespace
}  // namespace spira::test
