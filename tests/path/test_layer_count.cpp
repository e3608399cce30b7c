#include <gtest/gtest.h>

#include <vector>

#include "spira/path/layer_count.h"

using namespace spira;

TEST(LayerCount, FloorIsEquation314)
{
  EXPECT_EQ(countLayers({152.0, 160.0, 178.0}, 2.0, 1.8, 2.2, LayerMode::Floor), 84);  // floor(84.44)
  // 89.1 / 0.9 is 99 up to rounding: the count must not drop to 98.
  EXPECT_EQ(countLayers({89.1, 89.1}, 1.0, 0.9, 1.1, LayerMode::Floor), 99);
  EXPECT_EQ(countLayers({1.0, 5.0}, 2.0, 1.8, 2.2, LayerMode::Floor), 0);
}

TEST(LayerCount, CenteredPutsTheMeanStepNearestH)
{
  // mean 165, h = 2: 165/82 = 2.0122, 165/83 = 1.9880 -> 83, inside [ceil(178/2.2), floor(152/1.8)] = [81,
  // 84].
  EXPECT_EQ(countLayers({152.0, 165.0, 178.0}, 2.0, 1.8, 2.2, LayerMode::Centered), 83);
  // mean 105 -> 105, but 120/105 > 1.1: clamped to ceil(120/1.1) = 110 (<= floor(100/0.9) = 111).
  EXPECT_EQ(countLayers({100.0, 100.0, 100.0, 120.0}, 1.0, 0.9, 1.1, LayerMode::Centered), 110);
  // No count fits ([ceil(130/1.1), floor(90/0.9)] = [119, 100]): the centred count stays.
  EXPECT_EQ(countLayers({90.0, 130.0}, 1.0, 0.9, 1.1, LayerMode::Centered), 110);
  EXPECT_EQ(countLayers({1.0, 5.0}, 2.0, 1.8, 2.2, LayerMode::Centered), 0);
}

// Table 3.3: G in [152, 178] mm, 2 ± 0.2 mm: n_layer = 84, steps 1.81..2.12 mm, spread 0.31 <= 0.4: valid.
TEST(LayerCount, ThesisTable33Criterion)
{
  const LengthCriterion c = thesisLengthCriterion({152.0, 178.0, 165.0}, 1.8, 2.2);
  EXPECT_EQ(c.nLayers, 84);
  EXPECT_NEAR(c.stepSpread, 26.0 / 84.0, 1e-12);
  EXPECT_NEAR(c.window, 0.4, 1e-12);
  EXPECT_TRUE(c.ok);
  EXPECT_NEAR(c.lengthMin / c.nLayers, 1.81, 0.005);
  EXPECT_NEAR(c.lengthMax / c.nLayers, 2.12, 0.005);
  // 38 mm of difference over 84 layers is 0.45 mm per layer: more than the window.
  EXPECT_FALSE(thesisLengthCriterion({152.0, 190.0}, 1.8, 2.2).ok);
  EXPECT_FALSE(lengthCriterion({152.0, 178.0}, 0, 1.8, 2.2).ok);
}
