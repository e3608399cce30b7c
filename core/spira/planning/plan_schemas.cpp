#include "spira/planning/plan_schemas.h"

#include <cmath>
#include <variant>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/base/units.h"
#include "spira/path/calibration_table.h"
#include "spira/planning/settings_sections.h"
#include "spira/plugin/settings_binding.h"

namespace spira {
namespace {

// The sections as stored, before the values that mean "automatic" are resolved: the fields a
// plan uses plus the ones only the resolution reads.
struct StoredSpiral : SpiralSettings {
  double window = 0.0;  // fraction of h that h_min and h_max default to
};
struct StoredProcess : ProcessSettings {
  std::string calibrationFile;  // empty: mass conservation
};

using SpiralBinding = SettingsBinding<StoredSpiral>;
using ProcessBinding = SettingsBinding<StoredProcess>;

std::string mmText(double v)
{
  return significantText(v, 6) + " mm";
}

const SpiralBinding& spiralBinding()
{
  static const SpiralBinding binding({
      SpiralBinding::number(numberParam("h", 2.0, 0.05, 50.0, "mm",
                                        {"Nominal deposit height",
                                         "Mean height of one deposited layer (one revolution of the spiral).",
                                         "Process window"}),
                            &SpiralSettings::h),
      SpiralBinding::number(
          numberParam(
              "window", 10.0, 0.5, 90.0, "%",
              {"Modulation range",
               "Half-width of the process window around h, used when h_min or h_max is 0: the thesis's lab "
               "range is +/-10 %.",
               "Process window"}),
          &StoredSpiral::window),
      SpiralBinding::number(
          numberParam("h_min", 0.0, 0.0, 50.0, "mm",
                      {"Thinnest deposit",
                       "Smallest deposit height the process lays reliably. 0 = h minus the modulation range.",
                       "Process window"}),
          &SpiralSettings::hMin),
      SpiralBinding::number(
          numberParam("h_max", 0.0, 0.0, 50.0, "mm",
                      {"Thickest deposit",
                       "Largest deposit height the process lays reliably. 0 = h plus the modulation range.",
                       "Process window"}),
          &SpiralSettings::hMax),
      SpiralBinding::choice(
          "layer_mode", "centered", {{"floor", LayerMode::Floor}, {"centered", LayerMode::Centered}},
          {"Layer count",
           "floor: n = floor(min length / h_min) as in the thesis (Eq. 3.14), the mean deposit falls below "
           "h; "
           "centered: the mean deposit is brought back to h, staying inside the window when possible.",
           "Spiral"},
          &SpiralSettings::layerMode),
      SpiralBinding::choice("termination", "ramps",
                            {{"ramps", Termination::Ramps}, {"absorb", Termination::Absorb}},
                            {"Spiral end",
                             "ramps: mirrored ramps level the last revolution onto the upper edge or closure "
                             "point; absorb: the "
                             "thesis as written, the start-up climb is spread over the whole build.",
                             "Spiral"},
                            &SpiralSettings::termination),
      SpiralBinding::choice(
          "startup_transition", "uniform-helix",
          {{"uniform-helix", StartupTransition::UniformHelix}, {"to-nominal", StartupTransition::ToNominal}},
          {"Start-up transition",
           "uniform-helix: the start-up climbs what one revolution of the modulated phase climbs, so the "
           "seam "
           "is an ordinary step (the thesis's text); to-nominal: the transition ramp ends at h as the "
           "thesis's figures show, leaving a seam step of up to half the window.",
           "Spiral"},
          &SpiralSettings::startupTransition),
      SpiralBinding::number(
          numberParam(
              "closure_ring", 0.0, 0.0, 1000.0, "mm",
              {"Smallest closing ring",
               "Closed parts: the last revolutions around the closure point shorter than this are replaced "
               "by the closure point. 0 = pi x bead width, the smallest ring a bead of that width lays "
               "without covering itself.",
               "Spiral"}),
          &SpiralSettings::minRevolutionLength),
      SpiralBinding::number(
          numberParam(
              "height_tolerance", 0.5, 0.0, 10.0, "%",
              {"Window tolerance",
               "Heights within this fraction of h outside [h_min, h_max] still count as inside (Eq. 3.15).",
               "Spiral"}),
          &SpiralSettings::heightTolerance),
  });
  return binding;
}

const ProcessBinding& processBinding()
{
  static const ProcessBinding binding({
      ProcessBinding::choice(
          "process", "synergic",
          {{"synergic", ProcessMode::Synergic}, {"constant-ts", ProcessMode::ConstantTravelSpeed}},
          {"Process mode",
           "synergic: constant wire feed, the travel speed modulates the deposit (the thesis's CMT choice); "
           "constant-ts: constant travel speed, the wire feed modulates it.",
           "Process"},
          &ProcessSettings::mode),
      ProcessBinding::number(
          numberParam("wfs", 2.3, 0.1, 30.0, "m/min",
                      {"Wire-feed speed",
                       "Wire feed held constant in synergic mode, and the wire feed at which a "
                       "calibration table was measured.",
                       "Process"}),
          &ProcessSettings::wireFeed),
      ProcessBinding::number(
          numberParam("ts", 5.0, 0.1, 200.0, "mm/s",
                      {"Travel speed", "Travel speed held constant in constant-ts mode.", "Process"}),
          &ProcessSettings::travelSpeed),
      ProcessBinding::number(
          numberParam("wire_diameter", 1.0, 0.2, 5.0, "mm",
                      {"Wire diameter", "Filler wire diameter (mass conservation).", "Bead model"}),
          &ProcessSettings::wireDiameter),
      ProcessBinding::number(
          numberParam(
              "bead_width", 5.2, 0.5, 50.0, "mm",
              {"Bead width", "Width of the stabilised wall (mass conservation: h = pi d^2 WFS / (4 W TS)).",
               "Bead model"}),
          &ProcessSettings::beadWidth),
      ProcessBinding::text(
          pathParam("calibration",
                    {"Calibration table",
                     "CSV file with columns height_mm,travel_speed_mm_s measured at the wire-feed "
                     "speed above. Empty: use mass conservation.",
                     "Bead model"}),
          &StoredProcess::calibrationFile),
      ProcessBinding::number(
          numberParam("ts_min", 0.5, 0.0, 1000.0, "mm/s",
                      {"Minimum travel speed", "Slowest travel speed the process allows.", "Limits"}),
          [](StoredProcess& p) -> double& { return p.limits.travelSpeedMin; }),
      ProcessBinding::number(
          numberParam("ts_max", 50.0, 0.0, 1000.0, "mm/s",
                      {"Maximum travel speed", "Fastest travel speed the process allows.", "Limits"}),
          [](StoredProcess& p) -> double& { return p.limits.travelSpeedMax; }),
      ProcessBinding::number(
          numberParam("wfs_min", 0.5, 0.0, 60.0, "m/min",
                      {"Minimum wire-feed speed", "Slowest wire feed the power source allows.", "Limits"}),
          [](StoredProcess& p) -> double& { return p.limits.wireFeedMin; }),
      ProcessBinding::number(
          numberParam("wfs_max", 20.0, 0.0, 60.0, "m/min",
                      {"Maximum wire-feed speed", "Fastest wire feed the power source allows.", "Limits"}),
          [](StoredProcess& p) -> double& { return p.limits.wireFeedMax; }),
      ProcessBinding::flag(
          flagParam(
              "allow_slowdown", false,
              {"Let the controller slow down",
               "Where a robot or positioner axis would pass its speed limit at the planned travel speed, "
               "let the controller slow the move down. The wire feed keeps its setpoint, so the deposit "
               "thickens there: the plan reports by how much, point by point, and is infeasible only if "
               "the thicker deposit leaves the window. Off: any axis over its speed limit makes the plan "
               "infeasible.",
               "Limits"}),
          &ProcessSettings::allowSlowdown),
      ProcessBinding::number(
          numberParam(
              "positioner_tolerance", 2.0, 0.05, 15.0, "deg",
              {"Positioner tolerance",
               "How far from the vertical a positioner may leave the build direction (the flat welding "
               "position). Within it the table's rotation is free, so a spiral's climb per turn does not "
               "whip it round; smaller keeps the beads more level at the cost of more rotation.",
               "Limits"}),
          [](StoredProcess& p) -> double& { return p.positionerTiltTolerance; }),
      ProcessBinding::number(
          numberParam("torch_lead", 0.0, -45.0, 45.0, "deg",
                      {"Torch lead angle",
                       "Leans the torch off the build direction towards the travel direction (positive: "
                       "pushing) in the advance plane, theta_n of the source's tilt law. The bead is still "
                       "laid along the build direction, which a positioner keeps vertical.",
                       "Torch"}),
          [](StoredProcess& p) -> double& { return p.torchLead; }),
      ProcessBinding::number(
          numberParam("torch_side", 0.0, -45.0, 45.0, "deg",
                      {"Torch side angle",
                       "Leans the torch off the build direction towards the surface normal (positive: to the "
                       "outside of a wall), theta_t of the source's tilt law.",
                       "Torch"}),
          [](StoredProcess& p) -> double& { return p.torchSide; }),
  });
  return binding;
}

// h_min and h_max at 0 follow h and the modulation range; the window must hold h. The closing
// ring is left for withClosureRing().
SpiralSettings resolvedSpiral(const StoredSpiral& stored)
{
  SpiralSettings s = stored;
  if (s.hMin <= 0.0) s.hMin = s.h * (1.0 - stored.window);
  if (s.hMax <= 0.0) s.hMax = s.h * (1.0 + stored.window);
  if (s.hMin >= s.hMax)
    throw InputError(
        "the process window is empty: h_min = " + mmText(s.hMin) + " is not below h_max = " + mmText(s.hMax),
        "set --h-min below --h-max");
  if (s.h < s.hMin || s.h > s.hMax)
    throw InputError(
        "h = " + mmText(s.h) + " lies outside the window [" + mmText(s.hMin) + ", " + mmText(s.hMax) + "]",
        "choose h between h_min and h_max, or widen the window");
  return s;
}

// The closing ring at 0: pi x bead width, the smallest ring a bead of that width lays without
// covering itself.
SpiralSettings withClosureRing(SpiralSettings s, double beadWidth)
{
  if (s.minRevolutionLength <= 0.0) s.minRevolutionLength = kPi * beadWidth;
  return s;
}

ProcessSettings resolvedProcess(const StoredProcess& stored)
{
  ProcessSettings s = stored;
  if (s.limits.travelSpeedMin >= s.limits.travelSpeedMax)
    throw InputError("the travel-speed limits are crossed (ts_min >= ts_max)", "set --ts-min below --ts-max");
  if (s.limits.wireFeedMin >= s.limits.wireFeedMax)
    throw InputError("the wire-feed limits are crossed (wfs_min >= wfs_max)",
                     "set --wfs-min below --wfs-max");
  if (!stored.calibrationFile.empty()) {
    s.model = HeightModel::Calibration;
    s.calibration = readCalibrationCsv(stored.calibrationFile);
  }
  return s;
}

const ParamSet& sectionOf(const std::map<std::string, ParamSet>& params, const SettingsSection& section)
{
  static const ParamSet none;
  const auto it = params.find(std::string(section.name));
  return it == params.end() ? none : it->second;
}

}  // namespace

const ParamSchema& spiralSchema()
{
  return spiralBinding().schema();
}

const ParamSchema& processSchema()
{
  return processBinding().schema();
}

const SettingsSection& spiralSection()
{
  static const SettingsSection section{kSpiralSectionName, spiralSchema()};
  return section;
}

const SettingsSection& processSection()
{
  static const SettingsSection section{kProcessSectionName, processSchema()};
  return section;
}

const std::vector<SettingsSection>& planSections()
{
  static const std::vector<SettingsSection> sections{spiralSection(), processSection()};
  return sections;
}

ProcessSettings processSettingsFrom(const ParamSet& values)
{
  StoredProcess stored;
  processBinding().read(values, stored);
  return resolvedProcess(stored);
}

PlanSections readPlanSections(const std::map<std::string, ParamSet>& params)
{
  StoredSpiral stored;
  spiralBinding().read(sectionOf(params, spiralSection()), stored);
  const SpiralSettings spiral = resolvedSpiral(stored);
  PlanSections out;
  out.process = processSettingsFrom(sectionOf(params, processSection()));
  out.spiral = withClosureRing(spiral, out.process.beadWidth);
  return out;
}

double beadWidthOf(const ParamSet& values)
{
  const ParamDef* def = processSchema().find("bead_width");
  const double fallback = std::get<double>(def->defaultValue);
  if (!values.has("bead_width")) return fallback;
  const ParamValue& v = values.values().at("bead_width");
  const double* width = std::get_if<double>(&v);
  const bool inRange = width && std::isfinite(*width) && *width > 0.0 && (!def->min || *width >= *def->min) &&
                       (!def->max || *width <= *def->max);
  return inRange ? *width : fallback;
}

}  // namespace spira
