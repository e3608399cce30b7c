#include "spira/planning/plan_schemas.h"

#include <cmath>
#include <variant>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/path/calibration_table.h"

namespace spira {
namespace {

ParamDef num(std::string key, double def, double lo, double hi, std::string unit, std::string label,
             std::string tooltip, std::string category)
{
  return ParamDef{std::move(key),     ParamType::Double,   def, lo, hi, std::move(unit), std::move(label),
                  std::move(tooltip), std::move(category), {}};
}

ParamDef choice(std::string key, std::string def, std::vector<std::string> choices, std::string label,
                std::string tooltip, std::string category)
{
  return ParamDef{std::move(key),     ParamType::Choice,   std::move(def),    {}, {}, "", std::move(label),
                  std::move(tooltip), std::move(category), std::move(choices)};
}

std::string mmText(double v)
{
  return significantText(v, 6) + " mm";
}

}  // namespace

const ParamSchema& spiralSchema()
{
  static const ParamSchema schema({
      num("h", 2.0, 0.05, 50.0, "mm", "Nominal deposit height",
          "Mean height of one deposited layer (one revolution of the spiral).", "Process window"),
      num("window", 10.0, 0.5, 90.0, "%", "Modulation range",
          "Half-width of the process window around h, used when h_min or h_max is 0: the thesis's lab range "
          "is "
          "+/-10 %.",
          "Process window"),
      num("h_min", 0.0, 0.0, 50.0, "mm", "Thinnest deposit",
          "Smallest deposit height the process lays reliably. 0 = h minus the modulation range.",
          "Process window"),
      num("h_max", 0.0, 0.0, 50.0, "mm", "Thickest deposit",
          "Largest deposit height the process lays reliably. 0 = h plus the modulation range.",
          "Process window"),
      choice(
          "layer_mode", "centered", {"floor", "centered"}, "Layer count",
          "floor: n = floor(min length / h_min) as in the thesis (Eq. 3.14), the mean deposit falls below h; "
          "centered: the mean deposit is brought back to h, staying inside the window when possible.",
          "Spiral"),
      choice(
          "termination", "ramps", {"ramps", "absorb"}, "Spiral end",
          "ramps: mirrored ramps level the last revolution onto the upper edge or closure point; absorb: the "
          "thesis as written, the start-up climb is spread over the whole build.",
          "Spiral"),
      choice(
          "startup_transition", "uniform-helix", {"uniform-helix", "to-nominal"}, "Start-up transition",
          "uniform-helix: the start-up climbs what one revolution of the modulated phase climbs, so the seam "
          "is an ordinary step (the thesis's text); to-nominal: the transition ramp ends at h as the "
          "thesis's figures show, leaving a seam step of up to half the window.",
          "Spiral"),
      num("closure_ring", 0.0, 0.0, 1000.0, "mm", "Smallest closing ring",
          "Closed parts: the last revolutions around the closure point shorter than this are replaced by the "
          "closure point. 0 = pi x bead width, the smallest ring a bead of that width lays without covering "
          "itself.",
          "Spiral"),
      num("height_tolerance", 0.5, 0.0, 10.0, "%", "Window tolerance",
          "Heights within this fraction of h outside [h_min, h_max] still count as inside (Eq. 3.15).",
          "Spiral"),
  });
  return schema;
}

const ParamSchema& processSchema()
{
  static const ParamSchema schema({
      choice(
          "process", "synergic", {"synergic", "constant-ts"}, "Process mode",
          "synergic: constant wire feed, the travel speed modulates the deposit (the thesis's CMT choice); "
          "constant-ts: constant travel speed, the wire feed modulates it.",
          "Process"),
      num("wfs", 2.3, 0.1, 30.0, "m/min", "Wire-feed speed",
          "Wire feed held constant in synergic mode, and the wire feed at which a calibration table was "
          "measured.",
          "Process"),
      num("ts", 5.0, 0.1, 200.0, "mm/s", "Travel speed", "Travel speed held constant in constant-ts mode.",
          "Process"),
      num("wire_diameter", 1.0, 0.2, 5.0, "mm", "Wire diameter", "Filler wire diameter (mass conservation).",
          "Bead model"),
      num("bead_width", 5.2, 0.5, 50.0, "mm", "Bead width",
          "Width of the stabilised wall (mass conservation: h = pi d^2 WFS / (4 W TS)).", "Bead model"),
      ParamDef{
          "calibration",
          ParamType::Path,
          std::string(),
          {},
          {},
          "",
          "Calibration table",
          "CSV file with columns height_mm,travel_speed_mm_s measured at the wire-feed speed above. Empty: "
          "use mass conservation.",
          "Bead model",
          {}},
      num("ts_min", 0.5, 0.0, 1000.0, "mm/s", "Minimum travel speed",
          "Slowest travel speed the process allows.", "Limits"),
      num("ts_max", 50.0, 0.0, 1000.0, "mm/s", "Maximum travel speed",
          "Fastest travel speed the process allows.", "Limits"),
      num("wfs_min", 0.5, 0.0, 60.0, "m/min", "Minimum wire-feed speed",
          "Slowest wire feed the power source allows.", "Limits"),
      num("wfs_max", 20.0, 0.0, 60.0, "m/min", "Maximum wire-feed speed",
          "Fastest wire feed the power source allows.", "Limits"),
      ParamDef{"allow_slowdown",
               ParamType::Bool,
               false,
               {},
               {},
               "",
               "Let the controller slow down",
               "Where a robot or positioner axis would pass its speed limit at the planned travel speed, let "
               "the controller slow the move down. The wire feed keeps its setpoint, so the deposit thickens "
               "there: the plan reports by how much, point by point, and is infeasible only if the thicker "
               "deposit leaves the window. Off: any axis over its speed limit makes the plan infeasible.",
               "Limits",
               {}},
  });
  return schema;
}

SpiralSettings spiralSettingsFrom(const ParamSet& given)
{
  const ParamSchema& schema = spiralSchema();
  const ParamSet v = given.withDefaults(schema);
  schema.validate(v);
  SpiralSettings s;
  s.h = v.getDouble("h");
  const double window = v.internal(schema, "window");
  s.hMin = v.getDouble("h_min") > 0.0 ? v.getDouble("h_min") : s.h * (1.0 - window);
  s.hMax = v.getDouble("h_max") > 0.0 ? v.getDouble("h_max") : s.h * (1.0 + window);
  if (s.hMin >= s.hMax)
    throw InputError(
        "the process window is empty: h_min = " + mmText(s.hMin) + " is not below h_max = " + mmText(s.hMax),
        "set --h-min below --h-max");
  if (s.h < s.hMin || s.h > s.hMax)
    throw InputError(
        "h = " + mmText(s.h) + " lies outside the window [" + mmText(s.hMin) + ", " + mmText(s.hMax) + "]",
        "choose h between h_min and h_max, or widen the window");
  s.layerMode = v.getString("layer_mode") == "floor" ? LayerMode::Floor : LayerMode::Centered;
  s.termination = v.getString("termination") == "absorb" ? Termination::Absorb : Termination::Ramps;
  s.heightTolerance = v.internal(schema, "height_tolerance");
  s.startupTransition = v.getString("startup_transition") == "to-nominal" ? StartupTransition::ToNominal
                                                                          : StartupTransition::UniformHelix;
  s.minRevolutionLength = v.getDouble("closure_ring");
  return s;
}

ProcessSettings processSettingsFrom(const ParamSet& given)
{
  const ParamSchema& schema = processSchema();
  const ParamSet v = given.withDefaults(schema);
  schema.validate(v);
  ProcessSettings s;
  s.mode = v.getString("process") == "constant-ts" ? ProcessMode::ConstantTravelSpeed : ProcessMode::Synergic;
  s.wireFeed = v.internal(schema, "wfs");
  s.travelSpeed = v.internal(schema, "ts");
  s.wireDiameter = v.getDouble("wire_diameter");
  s.beadWidth = v.getDouble("bead_width");
  s.limits.travelSpeedMin = v.internal(schema, "ts_min");
  s.limits.travelSpeedMax = v.internal(schema, "ts_max");
  s.limits.wireFeedMin = v.internal(schema, "wfs_min");
  s.limits.wireFeedMax = v.internal(schema, "wfs_max");
  if (s.limits.travelSpeedMin >= s.limits.travelSpeedMax)
    throw InputError("the travel-speed limits are crossed (ts_min >= ts_max)", "set --ts-min below --ts-max");
  if (s.limits.wireFeedMin >= s.limits.wireFeedMax)
    throw InputError("the wire-feed limits are crossed (wfs_min >= wfs_max)",
                     "set --wfs-min below --wfs-max");
  s.allowSlowdown = v.getBool("allow_slowdown");
  const std::string& table = v.getString("calibration");
  if (!table.empty()) {
    s.model = HeightModel::Calibration;
    s.calibration = readCalibrationCsv(table);
  }
  return s;
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
