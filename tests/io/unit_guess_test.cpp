#include <gtest/gtest.h>

#include "spira/io/unit_guess.h"

namespace spira {
namespace {

BoundingBox box(double size)
{
  BoundingBox b;
  b.extend(Vec3(-size / 2, -size / 2, 0.0));
  b.extend(Vec3(size / 2, size / 2, size / 3));
  return b;
}

TEST(UnitGuess, AMetrePartReadAsMillimetresIsFlaggedWithTheFlag)
{
  const auto w = unitWarning(box(0.12), LengthUnit::Millimetre);
  ASSERT_TRUE(w);
  EXPECT_NE(w->find("0.12 mm across"), std::string::npos) << *w;
  EXPECT_NE(w->find("120 mm"), std::string::npos) << *w;
  EXPECT_NE(w->find("--unit m"), std::string::npos) << *w;
}

TEST(UnitGuess, AnInchOrCentimetrePartNamesBothUnits)
{
  const auto w = unitWarning(box(4.0), LengthUnit::Millimetre);
  ASSERT_TRUE(w);
  EXPECT_NE(w->find("--unit in"), std::string::npos) << *w;
  EXPECT_NE(w->find("102 mm"), std::string::npos) << *w;
  EXPECT_NE(w->find("--unit cm"), std::string::npos) << *w;
}

TEST(UnitGuess, PlausibleSizesAndDeclaredUnitsAreLeftAlone)
{
  EXPECT_FALSE(unitWarning(box(120.0), LengthUnit::Millimetre));
  EXPECT_FALSE(unitWarning(box(1500.0), LengthUnit::Millimetre));
  // 4 mm read from a file in inches is what the file says: only metres are still suspected below 3 mm.
  EXPECT_FALSE(unitWarning(box(4.0), LengthUnit::Inch));
  const auto huge = unitWarning(box(120.0 * 1000.0), LengthUnit::Metre);
  ASSERT_TRUE(huge);
  EXPECT_NE(huge->find("--unit mm"), std::string::npos) << *huge;
}

}  // namespace
}  // namespace spira
