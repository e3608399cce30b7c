#include <gtest/gtest.h>

#include "spira/base/error.h"
#include "spira/thermal/thermal_material.h"
#include "spira/thermal/thermal_solver.h"

namespace spira {
namespace {

TEST(ThermalMaterial, PresetsAreValidAndCiteTheirSource)
{
  for (const std::string& name : thermalMaterialPresetNames()) {
    const ThermalMaterial m = thermalMaterialPreset(name);
    EXPECT_EQ(m.name, name);
    EXPECT_NO_THROW(validateThermalMaterial(m));
    EXPECT_FALSE(m.source.empty());
    EXPECT_GT(m.meltingTemperature, m.solidusTemperature - 1e-9);
  }
  // The source's table 5.2, the values its simulations used.
  const ThermalMaterial steel = thermalMaterialPreset("G3Si1");
  EXPECT_EQ(steel.density, 7800.0);
  EXPECT_EQ(steel.conductivity, 60.0);
  EXPECT_EQ(steel.specificHeat, 470.0);
  EXPECT_EQ(steel.meltingTemperature, 1500.0);
  EXPECT_EQ(steel.inactiveDensity, 1.0);
  EXPECT_EQ(steel.inactiveConductivity, 0.026e-3);
  EXPECT_EQ(steel.inactiveSpecificHeat, 1160.0);
}

TEST(ThermalMaterial, UnknownNamesAndNonPositivePropertiesAreInputErrors)
{
  try {
    thermalMaterialPreset("unobtainium");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(e.hint().find("316L"), std::string::npos);
  }
  ThermalMaterial m = thermalMaterialPreset("316L");
  m.conductivity = 0.0;
  EXPECT_THROW(validateThermalMaterial(m), InputError);
  m = thermalMaterialPreset("316L");
  m.density = -1.0;
  EXPECT_THROW(validateThermalMaterial(m), InputError);
  m = thermalMaterialPreset("316L");
  m.emissivity = 1.5;
  EXPECT_THROW(validateThermalMaterial(m), InputError);
}

TEST(ThermalMaterial, ArcPowerIsEfficiencyTimesVoltageTimesCurrent)
{
  EXPECT_DOUBLE_EQ(arcPower(20.0, 150.0, 0.8), 2400.0);
  EXPECT_THROW(arcPower(0.0, 150.0, 0.8), InputError);
  EXPECT_THROW(arcPower(20.0, 150.0, 1.2), InputError);
}

}  // namespace
}  // namespace spira
