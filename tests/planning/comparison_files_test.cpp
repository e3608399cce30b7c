// compare.json and compare.csv as `spira-cli compare` writes them read back to the same comparison:
// the window, each strategy's verdict or failure, its points and heights.
#include <gtest/gtest.h>

#include <cmath>

#include "spira/base/units.h"
#include "spira/pipeline/comparison_reader.h"
#include "spira/planning/strategy_compare.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

TEST(ComparisonFiles, WrittenFilesReadBackToTheSameComparison)
{
  Comparison c;
  c.h = 2.0;
  c.hMin = 1.8;
  c.hMax = 2.2;
  StrategyOutcome helix;
  helix.strategy = "isovalue";
  helix.kind = "ctpp";
  helix.ran = helix.feasible = true;
  for (int i = 0; i < 40; ++i) {
    const double a = 2.0 * kPi * i / 20.0;
    helix.points.emplace_back(30.0 * std::cos(a), 30.0 * std::sin(a), 0.1 * i);
    helix.heights.push_back(1.9 + 0.005 * i);
  }
  StrategyOutcome failed;
  failed.strategy = "geodesic";
  failed.failure = "the part has no closure point";
  c.strategies = {helix, failed};
  TempDir dir;
  writeComparisonFiles(c, dir.path());

  const Comparison read = readComparison(dir.path());
  EXPECT_DOUBLE_EQ(read.hMin, 1.8);
  EXPECT_DOUBLE_EQ(read.hMax, 2.2);
  ASSERT_EQ(read.strategies.size(), 2u);
  EXPECT_TRUE(read.strategies[0].feasible);
  ASSERT_EQ(read.strategies[0].points.size(), 40u);
  EXPECT_LT((read.strategies[0].points[33] - helix.points[33]).norm(), 1e-9);
  EXPECT_DOUBLE_EQ(read.strategies[0].heights[17], helix.heights[17]);
  EXPECT_FALSE(read.strategies[1].ran);
  EXPECT_EQ(read.strategies[1].failure, "the part has no closure point");
}

}  // namespace
}  // namespace spira::test
