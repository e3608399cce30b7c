#include "spira/pipeline/prep_schema.h"

#include "spira/base/error.h"
#include "spira/plugin/settings_binding.h"

namespace spira {
namespace {

using PrepBinding = SettingsBinding<PrepParams>;

ParamText text(std::string label, std::string tooltip)
{
  return {std::move(label), std::move(tooltip), "Path preparation"};
}

const PrepBinding& prepBinding()
{
  static const PrepBinding binding({
      PrepBinding::flag(flagParam("smooth", true,
                                  text("Smooth the path",
                                       "Replace the polyline by a C2 quintic through its points before "
                                       "decimating (sharp corners stay).")),
                        &PrepParams::smooth),
      PrepBinding::number(
          numberParam("chord_tolerance", 0.05, 0.001, 5.0, "mm",
                      text("Chord tolerance",
                           "Greatest distance of a dropped point from the robot's straight move.")),
          &PrepParams::chordTolerance),
      PrepBinding::number(
          numberParam("height_change_tolerance", 0.02, 0.0001, 5.0, "mm",
                      text("Deposit-height tolerance",
                           "Greatest change of the deposit-height modulation a dropped point may cause.")),
          &PrepParams::heightTolerance),
      PrepBinding::number(numberParam("ts_tolerance", 0.2, 0.001, 100.0, "mm/s",
                                      text("Travel-speed tolerance",
                                           "Greatest change of the travel speed a dropped point may cause.")),
                          &PrepParams::travelSpeedTolerance),
      PrepBinding::number(numberParam("wfs_tolerance", 0.06, 0.0001, 10.0, "m/min",
                                      text("Wire-feed tolerance",
                                           "Greatest change of the wire feed a dropped point may cause.")),
                          &PrepParams::wireFeedTolerance),
      PrepBinding::number(
          numberParam("angle_tolerance", 1.0, 0.01, 30.0, "deg",
                      text("Torch-angle tolerance",
                           "Greatest change of the torch orientation a dropped point may cause.")),
          &PrepParams::orientationTolerance),
      PrepBinding::number(
          numberParam(
              "min_spacing", 0.5, 0.0, 100.0, "mm",
              text("Minimum point spacing",
                   "Points closer than this are merged (robots slow down on near-duplicate points).")),
          &PrepParams::minSpacing),
      PrepBinding::number(
          numberParam(
              "max_spacing", 5.0, 0.1, 1000.0, "mm",
              text("Maximum point spacing",
                   "Longest move written; Chalvin measured the path error growing with the point spacing.")),
          &PrepParams::maxSpacing),
      PrepBinding::flag(
          flagParam("wfs_lead", false,
                    text("Lead the wire feed",
                         "Write each wire-feed setpoint early, by the feeder's dead time and lag "
                         "below, so the feed reaches the planned value at its point (analog process "
                         "modes).")),
          &PrepParams::leadWireFeed),
      PrepBinding::number(
          numberParam("lead_dead_time", 0.1, 0.0, 5.0, "s",
                      text("Feeder dead time",
                           "Delay between a setpoint change and the first change of the wire feed.")),
          [](PrepParams& p) -> double& { return p.wireFeedLag.deadTime; }),
      PrepBinding::number(numberParam("lead_rise_time", 0.1, 0.001, 5.0, "s",
                                      text("Feeder rise time constant",
                                           "First-order time constant of the wire feed while it speeds up.")),
                          [](PrepParams& p) -> double& { return p.wireFeedLag.riseTimeConstant; }),
      PrepBinding::number(
          numberParam("lead_fall_time", 0.1, 0.001, 5.0, "s",
                      text("Feeder fall time constant",
                           "First-order time constant of the wire feed while it slows down.")),
          [](PrepParams& p) -> double& { return p.wireFeedLag.fallTimeConstant; }),
      PrepBinding::number(
          numberParam(
              "travel_clearance", 30.0, 1.0, 1000.0, "mm",
              text("Travel clearance",
                   "Between sub-paths (multi-branch parts) the torch backs off this far along its axis and "
                   "travels, arc off, this far above the highest point of the plan.")),
          &PrepParams::travelClearance),
      PrepBinding::number(
          numberParam("travel_speed", 50.0, 1.0, 2000.0, "mm/s",
                      text("Travel speed between sub-paths",
                           "Linear speed of the retract, travel and approach moves between sub-paths.")),
          &PrepParams::travelSpeed),
  });
  return binding;
}

}  // namespace

const ParamSchema& prepSchema()
{
  return prepBinding().schema();
}

const SettingsSection& prepSection()
{
  static const SettingsSection section{kPrepSectionName, prepSchema()};
  return section;
}

PrepParams prepParamsFrom(const ParamSet& values)
{
  PrepParams p;
  prepBinding().read(values, p);
  if (p.minSpacing >= p.maxSpacing)
    throw InputError("the minimum point spacing is not below the maximum",
                     "set --min-spacing below --max-spacing");
  return p;
}

}  // namespace spira
