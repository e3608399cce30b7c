#include "rapid_exporter.h"

#include <algorithm>
#include <iterator>
#include <memory>

#include "rapid_names.h"
#include "rapid_program.h"
#include "spira/base/error.h"
#include "spira/export/export_params.h"
#include "spira/export/export_steps.h"
#include "spira/export/fixed_number.h"
#include "spira/export/program_header.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {

namespace {

// RAPID's predefined zonedata (z0 ... z200): a program that names one needs no declaration.
constexpr int kZones[] = {0, 1, 5, 10, 15, 20, 30, 40, 50, 60, 80, 100, 150, 200};

ParamDef nameParam(const std::string& key, const std::string& value, const std::string& label,
                   const std::string& what)
{
  return textParam(key, value,
                   {label,
                    "RAPID name of the " + what +
                        " the program declares: at most 32 letters, digits or '_', starting with a letter, "
                        "not a reserved word nor a predefined name (tool0, v100, z1...).",
                    "Names"});
}

ParamSchema makeSchema()
{
  std::vector<ParamDef> defs;
  defs.push_back(
      programNameParam("spira_part",
                       "RAPID module names: at most 32 letters, digits or '_', starting with a letter, no "
                       "reserved word."));
  defs.push_back(maxPointsParam(
      5000, 100000,
      "Past it the targets go to part modules that the main module calls, with a .pgf program file."));
  defs.push_back(nameParam("tool_name", "tSpiraTorch", "Tool data", "torch tooldata (the cell's TCP)"));
  defs.push_back(nameParam("wobj_name", "wobjSpira", "Work object", "wobjdata the targets refer to"));
  defs.push_back(nameParam("seam_name", "smSpira", "Seam data", "seamdata (ignition, crater fill)"));
  defs.push_back(nameParam("weld_prefix", "wdSpira", "Weld data prefix",
                           "welddata, numbered from 1 (one per distinct speed and wire feed)"));
  defs.push_back(nameParam("speed_prefix", "vSpira", "Speed data prefix",
                           "speeddata, numbered from 1, and <prefix>Approach, <prefix>Travel"));
  defs.push_back(numberParam("tool_mass", 3.0, 0.1, 50.0, "kg",
                             {"Torch mass",
                              "tooldata load of the torch; its centre of gravity is put halfway to "
                              "the TCP. Measure it with LoadIdentify for accurate motion.",
                              "Frames"}));
  defs.push_back(intParam("zone", 1, 0, 200, "Zone (mm)",
                          "Predefined zonedata zN of the moves between the arc's ends (fine at them): one of "
                          "0, 1, 5, 10, 15, 20, 30, 40, 50, 60, 80, 100, 150, 200. Keep it below half the "
                          "point spacing.",
                          "Motion"));
  defs.push_back(approachDistanceParam());
  defs.push_back(approachSpeedParam(2000.0));
  defs.push_back(numberParam(
      "travel_speed", 200.0, 1.0, 5000.0, "mm/s",
      {"Travel speed", "v_tcp of the joint moves to the approach point and between sub-paths.", "Motion"}));
  defs.push_back(processCommandParam());
  defs.push_back(intParam("schedule", 1, 0, 999, "Weld schedule",
                          "arcdata sched: the power source's program (synergic line) of every welddata.",
                          "Process"));
  defs.push_back(numberParam("voltage", 0.0, 0.0, 60.0, "V",
                             {"Arc voltage", "arcdata voltage; 0 leaves it to the schedule.", "Process"}));
  defs.push_back(wfsDeadbandParam());
  defs.push_back(forceParam());
  return ParamSchema(std::move(defs));
}

// A data name as given, or the reason it cannot be one: data names are refused rather than fixed,
// since the user may refer to them elsewhere on the controller.
std::string checkedName(const ParamSet& values, const std::string& key, size_t room,
                        const std::string& example)
{
  const std::string name = values.getString(key);
  std::string problem = rapidDataNameProblem(name);
  if (problem.empty() && name.size() + room > 32)
    problem =
        "leaves no room for the " + std::to_string(room) + " characters the program appends (32 at most)";
  if (!problem.empty())
    throw InputError("RAPID export: " + key + " '" + name + "' " + problem,
                     "set " + key + " to a name of letters, digits and '_' starting with a letter, e.g. '" +
                         example + "'");
  return name;
}

}  // namespace

RapidExporter::RapidExporter() : schema_(makeSchema()) {}

std::string RapidExporter::description() const
{
  return "ABB IRC5 program (RobotWare Arc): ArcLStart/ArcL/ArcLEnd through robtargets with confdata and the "
         "positioner's external axes from the solved cell, one welddata per distinct weld speed and wire "
         "feed, "
         "split into called modules with a .pgf when long.";
}

ExportResult RapidExporter::write(const ExportInput& input, const ParamSet& params,
                                  const std::filesystem::path& outDir, Progress& progress) const
{
  const auto [values, options] = startExport(schema_, params, outDir, "abb_irc5");
  RapidSettings s;
  const std::string wanted = values.getString("program_name");
  s.moduleName = rapidModuleName(wanted);
  s.maxPoints = static_cast<size_t>(values.getInt("max_points"));
  s.toolName = checkedName(values, "tool_name", 0, "tSpiraTorch");
  s.wobjName = checkedName(values, "wobj_name", 0, "wobjSpira");
  s.seamName = checkedName(values, "seam_name", 0, "smSpira");
  s.weldPrefix = checkedName(values, "weld_prefix", 6, "wdSpira");
  s.speedPrefix = checkedName(values, "speed_prefix", 8, "vSpira");
  const std::vector<std::string> names{s.toolName,   s.wobjName,    s.seamName,
                                       s.weldPrefix, s.speedPrefix, s.moduleName};
  for (size_t a = 0; a < names.size(); ++a)
    for (size_t b = a + 1; b < names.size(); ++b)
      if (names[a] == names[b])
        throw InputError("RAPID export: the name '" + names[a] + "' is given to two things",
                         "give the module, tool, work object, seam and the prefixes different names");
  s.zone = static_cast<int>(values.getInt("zone"));
  if (std::find(std::begin(kZones), std::end(kZones), s.zone) == std::end(kZones))
    throw InputError("RAPID export: zone " + std::to_string(s.zone) + " is not a predefined zonedata",
                     "use one of 0, 1, 5, 10, 15, 20, 30, 40, 50, 60, 80, 100, 150, 200");
  s.toolMass = values.getDouble("tool_mass");
  s.approachSpeed = options.approachSpeed;
  s.travelSpeed = values.getDouble("travel_speed");
  s.wireFeed = options.process != ProcessCommand::Speed;
  s.schedule = static_cast<int>(values.getInt("schedule"));
  s.voltage = values.getDouble("voltage");

  const ExportPath path = prepareExportPath(input, options, progress);
  ExportResult result;
  result.warnings = path.warnings;
  if (s.moduleName != wanted)
    result.warnings.push_back(
        "program name '" + wanted +
        "' is not a valid RAPID module name (at most 32 letters, digits or '_', starting "
        "with a letter, no reserved word); written as '" +
        s.moduleName + "'");
  if (input.joints) s.flangeTcp = input.joints->flangeTcp;
  std::vector<std::pair<std::string, std::string>> settings;
  settings.emplace_back("module", s.moduleName);
  std::string length;
  appendFixed(length, path.length, 3);
  settings.emplace_back("points", std::to_string(path.points.size()) + ", path " + length + " mm");
  settings.emplace_back("frames", s.toolName + " (the cell's torch TCP), " + s.wobjName + " (identity)");
  if (path.hasJoints) {
    settings.emplace_back("targets", "torch TCP in the robot base frame of the solved cell, with confdata");
  } else {
    settings.emplace_back("targets", "torch TCP in the part frame (no solved cell), confdata 0");
    result.warnings.push_back(
        "no solved cell: the targets are torch poses in the part frame with confdata "
        "[0,0,0,0] and the tool is tool0; set " +
        s.wobjName + " to the measured part frame, " + s.toolName +
        " to the measured torch, and check the robot's configuration before running");
  }
  if (path.hasPositioner)
    settings.emplace_back("positioner", "E1/E2 in eax_a/eax_b, moving with each move (not coordinated)");
  settings.emplace_back("zone",
                        s.zone > 0 ? "z" + std::to_string(s.zone) + " inside arcs" : "fine everywhere");
  settings.emplace_back("process",
                        std::string(processCommandName(options.process)) + ", schedule " +
                            std::to_string(s.schedule) +
                            (s.wireFeed ? ", wire feed in welddata" : ", wire feed from the schedule"));
  if (path.arcCount > 1)
    settings.emplace_back("sub-paths", std::to_string(path.arcCount) +
                                           " arcs, ArcLStart/ArcLEnd each; MoveJ travel between sub-paths");
  if (path.hasLead && s.wireFeed)
    result.warnings.push_back(
        "the wire-feed lead is not applied in RAPID: a welddata takes effect with its ArcL");
  if (path.flaggedCount > 0)
    settings.emplace_back("forced",
                          std::to_string(path.flaggedCount) + " points flagged, see WARNING comments");
  const std::vector<std::string> header = programHeaderLines(input.header, settings);

  const RapidOutput out = writeRapidProgram(path, s, header, progress);
  if (out.worstSpeedError > 0.01)
    result.warnings.push_back(
        "weld speeds are written to three significant digits; the largest difference from the plan is " +
        std::to_string(static_cast<int>(std::lround(100.0 * out.worstSpeedError))) + " %");
  result.files = finishExport(outDir, out.files, progress);
  return result;
}

}  // namespace spira

void spira_register_export_rapid(spira::PluginRegistry& registry)
{
  registry.add(std::make_unique<spira::RapidExporter>());
}
