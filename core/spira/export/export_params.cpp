#include "spira/export/export_params.h"

#include "spira/base/error.h"

namespace spira {

namespace {

ParamDef def(std::string key, ParamType type, ParamValue value, std::string unit, std::string label,
             std::string tooltip, std::string category)
{
  ParamDef d;
  d.key = std::move(key);
  d.type = type;
  d.defaultValue = std::move(value);
  d.unit = std::move(unit);
  d.label = std::move(label);
  d.tooltip = std::move(tooltip);
  d.category = std::move(category);
  return d;
}

constexpr double kMmPerSPerMPerMin = 1000.0 / 60.0;

}  // namespace

ParamDef intParam(std::string key, std::int64_t value, double lo, double hi, std::string label,
                  std::string tooltip, std::string category)
{
  ParamDef d = def(std::move(key), ParamType::Int, value, "", std::move(label), std::move(tooltip),
                   std::move(category));
  d.min = lo;
  d.max = hi;
  return d;
}

ParamDef programNameParam(const std::string& defaultName, const std::string& rulesText)
{
  return def("program_name", ParamType::String, defaultName, "", "Program name",
             "Name of the program and of its files. " + rulesText +
                 " Other characters become '_'; a split program adds _001, _002... to its parts.",
             "Program");
}

ParamDef maxPointsParam(std::int64_t defaultCount, std::int64_t maxCount, const std::string& why)
{
  ParamDef d =
      def("max_points", ParamType::Int, defaultCount, "", "Points per program",
          "Largest number of positions in one program file. A longer path is split into numbered "
          "sub-programs that a main program calls in order, with the arc kept on across the calls. " +
              why,
          "Program");
  d.min = 10;
  d.max = static_cast<double>(maxCount);
  return d;
}

ParamDef approachDistanceParam()
{
  ParamDef d =
      def("approach_distance", ParamType::Double, 20.0, "mm", "Approach distance",
          "The torch arrives at the first point and leaves the last one along its own axis from this "
          "far back. 0 moves straight to the first point and ends on the last one.",
          "Motion");
  d.min = 0.0;
  d.max = 500.0;
  return d;
}

ParamDef approachSpeedParam(double maxSpeed)
{
  ParamDef d =
      def("approach_speed", ParamType::Double, 20.0, "mm/s", "Approach speed",
          "Linear speed of the approach to the first point and of the retract from the last one.", "Motion");
  d.min = 1.0;
  d.max = maxSpeed;
  return d;
}

ParamDef jointSpeedParam()
{
  ParamDef d =
      def("joint_speed", ParamType::Int, std::int64_t{20}, "%", "Joint move speed",
          "Speed, in percent of the axes' maximum, of the joint move to the approach point.", "Motion");
  d.min = 1;
  d.max = 100;
  return d;
}

ParamDef processCommandParam()
{
  ParamDef d = def("process_command", ParamType::Choice, std::string("speed"), "", "Process command",
                   "speed: every move runs at the plan's travel speed, the weld job sets the wire feed. "
                   "speed_analog: the same, plus the plan's wire-feed speed on an analog output. analog: one "
                   "constant travel speed and the wire feed on the analog output.",
                   "Process");
  d.choices = {"speed", "speed_analog", "analog"};
  return d;
}

ParamDef wfsOffsetParam(double lo, double hi, const std::string& outputText)
{
  ParamDef d = def("wfs_offset", ParamType::Double, 0.0, "", "WFS analog offset",
                   "Analog value = offset + gain x wire-feed speed (m/min). " + outputText, "Process");
  d.min = lo;
  d.max = hi;
  return d;
}

ParamDef wfsGainParam(double defaultGain, double lo, double hi, const std::string& outputText)
{
  ParamDef d =
      def("wfs_gain", ParamType::Double, defaultGain, "per m/min", "WFS analog gain",
          "Analog value per m/min of wire feed: value = offset + gain x WFS. " + outputText, "Process");
  d.min = lo;
  d.max = hi;
  return d;
}

ParamDef wfsDeadbandParam()
{
  ParamDef d = def("wfs_deadband", ParamType::Double, 0.05, "m/min", "WFS resolution",
                   "A new wire-feed setpoint is written only when the plan's wire feed has moved this much "
                   "since the last one, so the program is not flooded with output statements.",
                   "Process");
  d.min = 0.0;
  d.max = 10.0;
  return d;
}

ParamDef forceParam()
{
  return def("force", ParamType::Bool, false, "", "Export anyway",
             "Write the program even when points are unreachable, in collision or outside joint limits; "
             "each such move then carries a warning comment. Off, the export is refused.",
             "Checks");
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
