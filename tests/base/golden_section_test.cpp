#include "spira/base/golden_section.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace spira {
namespace {

TEST(GoldenSection, FindsTheMinimumOfAParabola)
{
  const auto f = [](double x) { return (x - 0.3) * (x - 0.3) + 2.0; };
  EXPECT_NEAR(goldenSectionMinimum(f, 0.0, 1.0, {200, 1e-12, GoldenTie::KeepLower}), 0.3, 1e-6);
  EXPECT_NEAR(goldenSectionMinimum(f, -4.0, 1.0, {200, 1e-12, GoldenTie::KeepUpper}), 0.3, 1e-6);
}

TEST(GoldenSection, FindsTheMinimumOfACosineOnAWideBracket)
{
  // cos has its one minimum over [2, 5] at pi.
  const auto f = [](double x) { return std::cos(x); };
  EXPECT_NEAR(goldenSectionMinimum(f, 2.0, 5.0, {200, 1e-12, GoldenTie::KeepLower}), std::acos(-1.0), 1e-6);
}

TEST(GoldenSection, EachStepShrinksTheBracketByTheGoldenRatio)
{
  // Without a tolerance every step is taken: two evaluations to start, one per step, and the
  // bracket left is 0.618^steps of the first one wide.
  std::vector<double> at;
  const auto f = [&](double x) {
    at.push_back(x);
    return std::abs(x - 0.75);
  };
  const int steps = 30;
  const double t = goldenSectionMinimum(f, 0.0, 1.0, {steps, 0.0, GoldenTie::KeepLower});
  EXPECT_EQ(at.size(), size_t(steps) + 2);
  EXPECT_NEAR(t, 0.75, std::pow(0.5 * (std::sqrt(5.0) - 1.0), steps));
  for (double x : at) {
    EXPECT_GT(x, 0.0);  // never the ends themselves
    EXPECT_LT(x, 1.0);
  }
}

TEST(GoldenSection, StopsOnceTheBracketIsNarrowerThanTheTolerance)
{
  int evaluations = 0;
  const auto f = [&](double x) {
    ++evaluations;
    return x * x;
  };
  goldenSectionMinimum(f, -1.0, 1.0, {1000, 1e-3, GoldenTie::KeepLower});
  // 2 * 0.618^k <= 1e-3 first at k = 16.
  EXPECT_EQ(evaluations, 16 + 2);
}

TEST(GoldenSection, TiesKeepTheNamedSideOfTheBracket)
{
  const auto flat = [](double) { return 1.0; };
  EXPECT_LT(goldenSectionMinimum(flat, 0.0, 1.0, {60, 0.0, GoldenTie::KeepLower}), 1e-9);
  EXPECT_GT(goldenSectionMinimum(flat, 0.0, 1.0, {60, 0.0, GoldenTie::KeepUpper}), 1.0 - 1e-9);
}

}  // namespace
}  // namespace spira
