#include "spira/pipeline/thermal_schema.h"

#include "spira/pipeline/thermal_stage.h"

#include <cmath>
#include <variant>

#include "spira/base/error.h"
#include "spira/plugin/settings_binding.h"

namespace spira {
namespace {

// The section as stored: counts arrive as numbers, the arc power as its three factors.
struct StoredThermal : ThermalStageSettings {
  std::string material = "G3Si1";
  double power = 1000.0, voltage = 0.0, current = 0.0, efficiency = 0.8;
  double emissivity = 0.0;
  double subSegments = 1.0, divisions = 1.0, frames = 200.0;
};

using ThermalBinding = SettingsBinding<StoredThermal>;

ParamText text(std::string label, std::string tooltip, const char* category)
{
  return {std::move(label), std::move(tooltip), category};
}

constexpr const char* kModel = "Thermal model";
constexpr const char* kArc = "Arc power";
constexpr const char* kResolution = "Resolution";
constexpr const char* kReplan = "Interpass limit and remedies";

ThermalBinding::Entry materialEntry()
{
  return {choiceParam("material", "G3Si1", thermalMaterialPresetNames(),
                      text("Material",
                           "The deposited alloy: its density, conductivity, specific heat and melting "
                           "temperature (thermal.md lists the sources).",
                           kModel)),
          [](StoredThermal& s, const ParamValue& v) { s.material = std::get<std::string>(v); }};
}

const ThermalBinding& thermalBinding()
{
  static const ThermalBinding binding({
      ThermalBinding::flag(
          flagParam("enabled", false,
                    text("Simulate heat",
                         "After the process stage, simulate the temperature of the deposit along the path: "
                         "peak and interpass temperature per point, the melt pool, collapse-risk zones. "
                         "Takes about half a minute on the dome.",
                         kModel)),
          &StoredThermal::enabled),
      materialEntry(),
      ThermalBinding::number(
          numberParam(
              "power", 1000.0, 0.0, 20000.0, "W",
              text("Arc power",
                   "Power reaching the part while the arc is on. 0 = voltage x current x efficiency.", kArc)),
          &StoredThermal::power),
      ThermalBinding::number(numberParam("voltage", 0.0, 0.0, 100.0, "V",
                                         text("Arc voltage", "Used when the arc power is 0.", kArc)),
                             &StoredThermal::voltage),
      ThermalBinding::number(numberParam("current", 0.0, 0.0, 1000.0, "A",
                                         text("Arc current", "Used when the arc power is 0.", kArc)),
                             &StoredThermal::current),
      ThermalBinding::number(
          numberParam("efficiency", 80.0, 1.0, 100.0, "%",
                      text("Arc efficiency",
                           "Share of the arc's power that enters the part (GMAW/CMT: 80 to 85 %).", kArc)),
          &StoredThermal::efficiency),
      ThermalBinding::number(
          numberParam("arc_radius", 0.0, 0.0, 20.0, "mm",
                      text("Arc radius",
                           "The arc as a Gaussian flux of this radius (95 % of the power inside it). "
                           "0 = half the bead width.",
                           kArc)),
          &StoredThermal::arcRadius),
      ThermalBinding::number(
          numberParam(
              "emissivity", 0.0, 0.0, 1.0, "",
              text("Emissivity", "Radiation from both faces of the laid wall. 0 = none (the source's model).",
                   kModel)),
          [](StoredThermal& s) -> double& { return s.emissivity; }),
      ThermalBinding::number(
          numberParam(
              "time_step", 0.0, 0.0, 60.0, "s",
              text("Time step", "0 = automatic: the torch moves one sub-segment per step.", kResolution)),
          [](StoredThermal& s) -> double& { return s.study.solver.timeStep; }),
      ThermalBinding::number(
          integerParam("sub_segments", 1, 1, 64,
                       text("Sub-segments", "Mesh sub-segments per planned segment (k).", kResolution)),
          &StoredThermal::subSegments),
      ThermalBinding::number(
          integerParam("divisions", 1, 1, 16,
                       text("Divisions", "Element rows across each layer (f).", kResolution)),
          &StoredThermal::divisions),
      ThermalBinding::number(
          // Two minutes by default (spira-cli thermal: none), so the frames show the last layers
          // cooling too and the probe chart of a point near the end has a history.
          numberParam("cooling", 120.0, 0.0, 36000.0, "s",
                      text("Cooling time", "Time simulated after the arc stops.", kResolution)),
          [](StoredThermal& s) -> double& { return s.study.solver.coolingTime; }),
      ThermalBinding::number(
          integerParam(
              "frames", 200, 0, 2000,
              text("Frames", "Snapshots of the field kept for playback (in the project file).", kResolution)),
          &StoredThermal::frames),
      ThermalBinding::number(
          numberParam(
              "bond_threshold", kDefaultBondThreshold, 0.1, 100.0, "",
              text("Bond threshold",
                   "A point is at risk of collapse when its pool's weighted Bond number exceeds this.",
                   kModel)),
          [](StoredThermal& s) -> double& { return s.study.bondThreshold; }),
      ThermalBinding::number(
          numberParam("interpass_max", 0.0, 0.0, 3000.0, "°C",
                      text("Interpass limit",
                           "The hottest the deposit below may be when the torch comes back over it; drawn on "
                           "the probe chart and counted per point. 0 = no limit.",
                           kReplan)),
          &StoredThermal::interpassLimit),
      ThermalBinding::flag(
          flagParam(
              "remedy_deposit", false,
              text("Re-plan: thinner layers",
                   "Where the interpass limit is exceeded, lay that band with more, thinner revolutions "
                   "at the same wire feed, so faster (the source's remedy), no thinner than h_min; one "
                   "spiral still. Tried first; kept only if the simulation finds it cooler.",
                   kReplan)),
          &StoredThermal::remedyDeposit),
      ThermalBinding::flag(
          flagParam("remedy_heat", true,
                    text("Re-plan: less heat",
                         "Where the interpass limit is exceeded, slow the wire feed and the travel speed "
                         "together (same deposit, same single spiral, less arc power), down to the process's "
                         "slowest speeds, and simulate again until the limit holds.",
                         kReplan)),
          &StoredThermal::remedyHeat),
      ThermalBinding::flag(
          flagParam(
              "remedy_dwell", false,
              text("Re-plan: dwell",
                   "Where the limit still is exceeded, stop before the revolution, lift the torch with the "
                   "arc off and wait until the part has cooled. Each dwell adds an arc start.",
                   kReplan)),
          &StoredThermal::remedyDwell),
      ThermalBinding::number(
          numberParam("max_dwell", 600.0, 1.0, 36000.0, "s",
                      text("Longest dwell", "The longest single wait the dwell remedy may add.", kReplan)),
          &StoredThermal::maxDwell),
  });
  return binding;
}

}  // namespace

const ParamSchema& thermalSchema()
{
  return thermalBinding().schema();
}

const SettingsSection& thermalSection()
{
  static const SettingsSection section{kThermalSectionName, thermalSchema()};
  return section;
}

bool thermalStageEnabled(const ParamSet& values)
{
  if (!values.has("enabled")) return false;
  const bool* on = std::get_if<bool>(&values.values().at("enabled"));
  return on && *on;
}

ThermalStageSettings thermalStageSettingsFrom(const ParamSet& values)
{
  StoredThermal stored;
  thermalBinding().read(values, stored);
  ThermalStageSettings out = stored;
  ThermalSettings& solver = out.study.solver;
  solver.material = thermalMaterialPreset(stored.material);
  solver.material.emissivity = stored.emissivity;
  if (stored.power > 0.0)
    solver.power = stored.power;
  else if (stored.voltage > 0.0 && stored.current > 0.0)
    solver.power = arcPower(stored.voltage, stored.current, stored.efficiency);
  else
    throw InputError("the thermal stage has no arc power: power is 0 and voltage or current is 0",
                     "set the arc power, or the arc voltage and current");
  out.study.mesh.subSegments = static_cast<int>(stored.subSegments);
  out.study.mesh.divisions = static_cast<int>(stored.divisions);
  out.study.frames = static_cast<int>(stored.frames);
  return out;
}

}  // namespace spira
