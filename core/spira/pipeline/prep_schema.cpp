#include "spira/pipeline/prep_schema.h"

#include "spira/base/error.h"
#include "spira/base/units.h"

namespace spira {
namespace {

ParamDef num(std::string key, double def, double lo, double hi, std::string unit, std::string label,
             std::string tooltip)
{
  return ParamDef{std::move(key),     ParamType::Double,  def, lo, hi, std::move(unit), std::move(label),
                  std::move(tooltip), "Path preparation", {}};
}

}  // namespace

const ParamSchema& prepSchema()
{
  static const ParamSchema schema({
      ParamDef{
          "smooth",
          ParamType::Bool,
          true,
          {},
          {},
          "",
          "Smooth the path",
          "Replace the polyline by a C2 quintic through its points before decimating (sharp corners stay).",
          "Path preparation",
          {}},
      num("chord_tolerance", 0.05, 0.001, 5.0, "mm", "Chord tolerance",
          "Greatest distance of a dropped point from the robot's straight move."),
      num("height_change_tolerance", 0.02, 0.0001, 5.0, "mm", "Deposit-height tolerance",
          "Greatest change of the deposit-height modulation a dropped point may cause."),
      num("ts_tolerance", 0.2, 0.001, 100.0, "mm/s", "Travel-speed tolerance",
          "Greatest change of the travel speed a dropped point may cause."),
      num("wfs_tolerance", 0.06, 0.0001, 10.0, "m/min", "Wire-feed tolerance",
          "Greatest change of the wire feed a dropped point may cause."),
      num("angle_tolerance", 1.0, 0.01, 30.0, "deg", "Torch-angle tolerance",
          "Greatest change of the torch orientation a dropped point may cause."),
      num("min_spacing", 0.5, 0.0, 100.0, "mm", "Minimum point spacing",
          "Points closer than this are merged (robots slow down on near-duplicate points)."),
      num("max_spacing", 5.0, 0.1, 1000.0, "mm", "Maximum point spacing",
          "Longest move written; Chalvin measured the path error growing with the point spacing."),
      ParamDef{"wfs_lead",
               ParamType::Bool,
               false,
               {},
               {},
               "",
               "Lead the wire feed",
               "Write each wire-feed setpoint early, by the feeder's dead time and lag below, so the feed "
               "reaches the planned value at its point (analog process modes).",
               "Path preparation",
               {}},
      num("lead_dead_time", 0.1, 0.0, 5.0, "s", "Feeder dead time",
          "Delay between a setpoint change and the first change of the wire feed."),
      num("lead_rise_time", 0.1, 0.001, 5.0, "s", "Feeder rise time constant",
          "First-order time constant of the wire feed while it speeds up."),
      num("lead_fall_time", 0.1, 0.001, 5.0, "s", "Feeder fall time constant",
          "First-order time constant of the wire feed while it slows down."),
      num("travel_clearance", 30.0, 1.0, 1000.0, "mm", "Travel clearance",
          "Between sub-paths (multi-branch parts) the torch backs off this far along its axis and travels, "
          "arc off, this far above the highest point of the plan."),
      num("travel_speed", 50.0, 1.0, 2000.0, "mm/s", "Travel speed between sub-paths",
          "Linear speed of the retract, travel and approach moves between sub-paths."),
  });
  return schema;
}

PrepParams prepParamsFrom(const ParamSet& given)
{
  const ParamSchema& schema = prepSchema();
  const ParamSet v = given.withDefaults(schema);
  schema.validate(v);
  PrepParams p;
  p.smooth = v.getBool("smooth");
  p.chordTolerance = v.getDouble("chord_tolerance");
  p.heightTolerance = v.getDouble("height_change_tolerance");
  p.travelSpeedTolerance = v.getDouble("ts_tolerance");
  p.wireFeedTolerance = v.getDouble("wfs_tolerance") * 1000.0 / 60.0;
  p.orientationTolerance = degToRad(v.getDouble("angle_tolerance"));
  p.minSpacing = v.getDouble("min_spacing");
  p.maxSpacing = v.getDouble("max_spacing");
  p.leadWireFeed = v.getBool("wfs_lead");
  p.wireFeedLag.deadTime = v.getDouble("lead_dead_time");
  p.wireFeedLag.riseTimeConstant = v.getDouble("lead_rise_time");
  p.wireFeedLag.fallTimeConstant = v.getDouble("lead_fall_time");
  p.travelClearance = v.getDouble("travel_clearance");
  p.travelSpeed = v.getDouble("travel_speed");
  if (p.minSpacing >= p.maxSpacing)
    throw InputError("the minimum point spacing is not below the maximum",
                     "set --min-spacing below --max-spacing");
  return p;
}

}  // namespace spira
