#pragma once

#include <string>
#include <vector>

namespace spira {

// The constant (temperature-independent) properties of a deposited alloy, as the source's linear
// model uses them (000_dbb97c2716e10cc3.txt, chapter 5: no latent heat, no radiation by default).
// SI units, temperatures in degrees Celsius.
struct ThermalMaterial {
  std::string name;
  double density = 0.0;             // kg/m3, solid
  double conductivity = 0.0;        // W/(m K)
  double specificHeat = 0.0;        // J/(kg K)
  double meltingTemperature = 0.0;  // C: above it a node counts as weld pool
  double solidusTemperature = 0.0;  // C
  double surfaceTension = 0.0;      // N/m, for the Bond number of the pool
  double liquidDensity = 0.0;       // kg/m3
  double emissivity = 0.0;          // 0 = no radiation (the source's choice)
  // Properties of not yet deposited ("inactive") elements: the source's Table 5.2 (an air-like
  // filler, so that the matrix pattern never changes while heat barely enters the unborn deposit).
  double inactiveDensity = 1.0;
  double inactiveConductivity = 0.026e-3;
  double inactiveSpecificHeat = 1160.0;
  // Suggested maximum interpass temperature, C; 0 when the literature gives no single value.
  double interpassLimit = 0.0;
  std::string source;  // where the numbers come from

  double volumetricHeat() const { return density * specificHeat; }                          // J/(m3 K)
  double inactiveVolumetricHeat() const { return inactiveDensity * inactiveSpecificHeat; }  // J/(m3 K)
};

// The presets by name: "G3Si1" (the source's steel), "316L", "Ti-6Al-4V", "AlMg5".
// Throws InputError naming the known presets for an unknown name.
ThermalMaterial thermalMaterialPreset(const std::string& name);
std::vector<std::string> thermalMaterialPresetNames();

// Throws InputError with a hint when a property the model divides by or multiplies with is not
// positive (or the emissivity is outside [0, 1], or the solidus is above the melting temperature).
void validateThermalMaterial(const ThermalMaterial& m);

}  // namespace spira
