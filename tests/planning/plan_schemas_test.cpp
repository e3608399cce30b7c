// The process settings as views read them: the bead width never throws, whatever a file stored.
#include <gtest/gtest.h>

#include <limits>

#include "spira/base/error.h"
#include "spira/planning/plan_schemas.h"
#include "spira/plugin/parameter.h"

namespace spira {
namespace {

TEST(PlanSchemas, BeadWidthIsReadWithoutValidatingTheRest)
{
  const double fallback = std::get<double>(processSchema().find("bead_width")->defaultValue);
  ParamSet values;
  EXPECT_EQ(beadWidthOf(values), fallback);
  values.set("bead_width", 6.5);
  values.set("ts_min", 30.0);
  values.set("ts_max", 10.0);
  EXPECT_THROW(processSettingsFrom(values), InputError);
  EXPECT_EQ(beadWidthOf(values), 6.5);
  for (const ParamValue& bad : {ParamValue(-1.0), ParamValue(std::numeric_limits<double>::quiet_NaN()),
                                ParamValue(1e9), ParamValue(std::string("wide"))}) {
    values.set("bead_width", bad);
    EXPECT_EQ(beadWidthOf(values), fallback);
  }
}

}  // namespace
}  // namespace spira
