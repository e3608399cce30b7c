// One default per setting: the settings structs the path, process and preparation code use
// default to what the schemas (panels, CLI flags, project files) default to.
#include <gtest/gtest.h>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/pipeline/prep_schema.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/settings_sections.h"

namespace spira {
namespace {

TEST(SettingsDefaults, EmptySectionsReadAsTheDefaultSpiralSettings)
{
  const SpiralSettings read = readPlanSections({}).spiral;
  const SpiralSettings def;
  EXPECT_DOUBLE_EQ(read.h, def.h);
  EXPECT_DOUBLE_EQ(read.hMin, def.hMin);
  EXPECT_DOUBLE_EQ(read.hMax, def.hMax);
  EXPECT_EQ(read.layerMode, def.layerMode);
  EXPECT_EQ(read.startupTransition, def.startupTransition);
  EXPECT_EQ(read.termination, def.termination);
  EXPECT_DOUBLE_EQ(read.heightTolerance, def.heightTolerance);
  EXPECT_DOUBLE_EQ(read.minRevolutionLength, def.minRevolutionLength);
}

TEST(SettingsDefaults, EmptySectionsReadAsTheDefaultProcessSettings)
{
  const ProcessSettings read = readPlanSections({}).process;
  const ProcessSettings def;
  EXPECT_EQ(read.mode, def.mode);
  EXPECT_EQ(read.model, def.model);
  EXPECT_DOUBLE_EQ(read.wireDiameter, def.wireDiameter);
  EXPECT_DOUBLE_EQ(read.beadWidth, def.beadWidth);
  EXPECT_DOUBLE_EQ(read.wireFeed, def.wireFeed);
  EXPECT_DOUBLE_EQ(read.travelSpeed, def.travelSpeed);
  EXPECT_TRUE(read.calibration.heights().empty());
  EXPECT_DOUBLE_EQ(read.limits.travelSpeedMin, def.limits.travelSpeedMin);
  EXPECT_DOUBLE_EQ(read.limits.travelSpeedMax, def.limits.travelSpeedMax);
  EXPECT_DOUBLE_EQ(read.limits.wireFeedMin, def.limits.wireFeedMin);
  EXPECT_DOUBLE_EQ(read.limits.wireFeedMax, def.limits.wireFeedMax);
  EXPECT_EQ(read.clampToLimits, def.clampToLimits);
  EXPECT_EQ(read.allowSlowdown, def.allowSlowdown);
}

TEST(SettingsDefaults, AnEmptyPrepSectionReadsAsTheDefaultPrepParams)
{
  const PrepParams read = prepParamsFrom(ParamSet());
  const PrepParams def;
  EXPECT_EQ(read.smooth, def.smooth);
  EXPECT_DOUBLE_EQ(read.chordTolerance, def.chordTolerance);
  EXPECT_DOUBLE_EQ(read.heightTolerance, def.heightTolerance);
  EXPECT_DOUBLE_EQ(read.travelSpeedTolerance, def.travelSpeedTolerance);
  EXPECT_DOUBLE_EQ(read.wireFeedTolerance, def.wireFeedTolerance);
  EXPECT_DOUBLE_EQ(read.orientationTolerance, def.orientationTolerance);
  EXPECT_DOUBLE_EQ(read.minSpacing, def.minSpacing);
  EXPECT_DOUBLE_EQ(read.maxSpacing, def.maxSpacing);
  EXPECT_EQ(read.leadWireFeed, def.leadWireFeed);
  EXPECT_DOUBLE_EQ(read.wireFeedLag.deadTime, def.wireFeedLag.deadTime);
  EXPECT_DOUBLE_EQ(read.wireFeedLag.riseTimeConstant, def.wireFeedLag.riseTimeConstant);
  EXPECT_DOUBLE_EQ(read.wireFeedLag.fallTimeConstant, def.wireFeedLag.fallTimeConstant);
  EXPECT_DOUBLE_EQ(read.travelClearance, def.travelClearance);
  EXPECT_DOUBLE_EQ(read.travelSpeed, def.travelSpeed);
}

// The values that mean "automatic" are resolved where the sections are read: h_min and h_max
// from h and the modulation range, the closing ring from the process section's bead width.
TEST(SettingsDefaults, AutomaticValuesFollowTheOtherSettings)
{
  std::map<std::string, ParamSet> params;
  params["spiral"].set("h", 3.0);
  params["spiral"].set("window", 20.0);
  params["process"].set("bead_width", 8.0);
  const PlanSections read = readPlanSections(params);
  EXPECT_DOUBLE_EQ(read.spiral.hMin, 2.4);
  EXPECT_DOUBLE_EQ(read.spiral.hMax, 3.6);
  EXPECT_DOUBLE_EQ(read.spiral.minRevolutionLength, kPi * 8.0);
  params["spiral"].set("closure_ring", 12.0);
  params["spiral"].set("h_max", 3.1);
  EXPECT_DOUBLE_EQ(readPlanSections(params).spiral.minRevolutionLength, 12.0);
  EXPECT_DOUBLE_EQ(readPlanSections(params).spiral.hMax, 3.1);
  params["spiral"].set("h_max", 2.9);
  EXPECT_THROW(readPlanSections(params), InputError);  // h above the window
}

TEST(SettingsDefaults, ConversionsAndChoicesReachTheirFields)
{
  std::map<std::string, ParamSet> params;
  params["spiral"].set("layer_mode", std::string("floor"));
  params["spiral"].set("termination", std::string("absorb"));
  params["spiral"].set("startup_transition", std::string("to-nominal"));
  params["spiral"].set("height_tolerance", 2.0);
  params["process"].set("process", std::string("constant-ts"));
  params["process"].set("wfs", 6.0);
  params["process"].set("wfs_max", 12.0);
  params["process"].set("allow_slowdown", true);
  const PlanSections read = readPlanSections(params);
  EXPECT_EQ(read.spiral.layerMode, LayerMode::Floor);
  EXPECT_EQ(read.spiral.termination, Termination::Absorb);
  EXPECT_EQ(read.spiral.startupTransition, StartupTransition::ToNominal);
  EXPECT_DOUBLE_EQ(read.spiral.heightTolerance, 0.02);
  EXPECT_EQ(read.process.mode, ProcessMode::ConstantTravelSpeed);
  EXPECT_DOUBLE_EQ(read.process.wireFeed, 100.0);            // 6 m/min in mm/s
  EXPECT_DOUBLE_EQ(read.process.limits.wireFeedMax, 200.0);  // 12 m/min
  EXPECT_TRUE(read.process.allowSlowdown);
}

// Section names are the keys of project files, presets and report.json: they never change.
TEST(SettingsSections, NamesAndSchemasOfThePlannersSections)
{
  ASSERT_EQ(planSections().size(), 2u);
  EXPECT_EQ(planSections()[0].name, "spiral");
  EXPECT_EQ(planSections()[1].name, "process");
  EXPECT_EQ(&planSections()[0].schema, &spiralSchema());
  EXPECT_EQ(&planSections()[1].schema, &processSchema());
  EXPECT_EQ(prepSection().name, "prep");
  EXPECT_EQ(&prepSection().schema, &prepSchema());
  EXPECT_NE(spiralSchema().find("closure_ring"), nullptr);
  EXPECT_NE(processSchema().find("calibration"), nullptr);
  EXPECT_EQ(processSchema().find("calibration")->type, ParamType::Path);
}

}  // namespace
}  // namespace spira
