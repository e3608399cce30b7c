#include "spira/export/export_params.h"

#include "spira/base/error.h"

namespace spira {

namespace {

constexpr double kMmPerSPerMPerMin = 1000.0 / 60.0;

}  // namespace

ParamDef intParam(std::string key, std::int64_t value, double lo, double hi, std::string label,
                  std::string tooltip, std::string category)
{
  return integerParam(std::move(key), value, static_cast<std::int64_t>(lo), static_cast<std::int64_t>(hi),
                      {std::move(label), std::move(tooltip), std::move(category)});
}

ParamDef programNameParam(const std::string& defaultName, const std::string& rulesText)
{
  return textParam("program_name", defaultName,
                   {"Program name",
                    "Name of the program and of its files. " + rulesText +
                        " Other characters become '_'; a split program adds _001, _002... to its parts.",
                    "Program"});
}

ParamDef maxPointsParam(std::int64_t defaultCount, std::int64_t maxCount, const std::string& why)
{
  return integerParam(
      "max_points", defaultCount, 10, maxCount,
      {"Points per program",
       "Largest number of positions in one program file. A longer path is split into numbered "
       "sub-programs that a main program calls in order, with the arc kept on across the calls. " +
           why,
       "Program"});
}

ParamDef approachDistanceParam()
{
  return numberParam(
      "approach_distance", 20.0, 0.0, 500.0, "mm",
      {"Approach distance",
       "The torch arrives at the first point and leaves the last one along its own axis from this "
       "far back. 0 moves straight to the first point and ends on the last one.",
       "Motion"});
}

ParamDef approachSpeedParam(double maxSpeed)
{
  return numberParam(
      "approach_speed", 20.0, 1.0, maxSpeed, "mm/s",
      {"Approach speed",
       "Linear speed of the approach to the first point and of the retract from the last one.", "Motion"});
}

ParamDef jointSpeedParam()
{
  ParamDef d = integerParam(
      "joint_speed", 20, 1, 100,
      {"Joint move speed", "Speed, in percent of the axes' maximum, of the joint move to the approach point.",
       "Motion"});
  d.unit = "%";
  return d;
}

ParamDef processCommandParam()
{
  return choiceParam(
      "process_command", "speed", {"speed", "speed_analog", "analog"},
      {"Process command",
       "speed: every move runs at the plan's travel speed, the weld job sets the wire feed. "
       "speed_analog: the same, plus the plan's wire-feed speed on an analog output. analog: one "
       "constant travel speed and the wire feed on the analog output.",
       "Process"});
}

ParamDef wfsOffsetParam(double lo, double hi, const std::string& outputText)
{
  return numberParam("wfs_offset", 0.0, lo, hi, "",
                     {"WFS analog offset",
                      "Analog value = offset + gain x wire-feed speed (m/min). " + outputText, "Process"});
}

ParamDef wfsGainParam(double defaultGain, double lo, double hi, const std::string& outputText)
{
  return numberParam(
      "wfs_gain", defaultGain, lo, hi, "per m/min",
      {"WFS analog gain", "Analog value per m/min of wire feed: value = offset + gain x WFS. " + outputText,
       "Process"});
}

ParamDef wfsDeadbandParam()
{
  return numberParam(
      "wfs_deadband", 0.05, 0.0, 10.0, "m/min",
      {"WFS resolution",
       "A new wire-feed setpoint is written only when the plan's wire feed has moved this much "
       "since the last one, so the program is not flooded with output statements.",
       "Process"});
}

ParamDef forceParam()
{
  return flagParam(
      "force", false,
      {"Export anyway",
       "Write the program even when points are unreachable, in collision or outside joint limits; "
       "each such move then carries a warning comment. Off, the export is refused.",
       "Checks"});
}

PathOptions readPathOptions(const ParamSet& values, const ParamSchema& schema, const std::string& controller)
{
  PathOptions o;
  o.controller = controller;
  o.approachDistance = values.internal(schema, "approach_distance");
  o.approachSpeed = values.internal(schema, "approach_speed");
  const std::string& mode = values.getString("process_command");
  o.process = mode == "speed_analog" ? ProcessCommand::SpeedAnalog
              : mode == "analog"     ? ProcessCommand::Analog
                                     : ProcessCommand::Speed;
  o.wfsDeadband = values.internal(schema, "wfs_deadband");
  o.force = values.getBool("force");
  return o;
}

double wfsAnalogValue(double wfsMmPerS, double offset, double gainPerMPerMin)
{
  return offset + gainPerMPerMin * (wfsMmPerS / kMmPerSPerMPerMin);
}

const char* processCommandName(ProcessCommand c)
{
  switch (c) {
    case ProcessCommand::Speed:
      return "speed";
    case ProcessCommand::SpeedAnalog:
      return "speed_analog";
    case ProcessCommand::Analog:
      return "analog";
  }
  return "speed";
}

}  // namespace spira
