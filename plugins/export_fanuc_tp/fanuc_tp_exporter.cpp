#include "fanuc_tp_exporter.h"

#include <cmath>
#include <memory>

#include "fanuc_tp_positions.h"
#include "fanuc_tp_program.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/export/export_params.h"
#include "spira/export/export_steps.h"
#include "spira/export/fixed_number.h"
#include "spira/export/program_header.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {

namespace {

ParamSchema makeSchema()
{
  std::vector<ParamDef> defs;
  defs.push_back(programNameParam(
      "SPIRA_PART", "TP names: at most 36 capital letters, digits or '_', starting with a letter."));
  defs.push_back(maxPointsParam(9000, 15000,
                                "An R-30iB takes at most 15,000 positions per program; the default keeps /MN "
                                "under 9,999 lines as offline tools usually do."));
  defs.push_back(
      intParam("uframe", 0, 0, 9, "User frame",
               "UFRAME_NUM of the targets. With a solved cell they are in the robot's World frame, so "
               "use 0; without one they are in the part frame, so use the frame measured on the part.",
               "Frames"));
  defs.push_back(intParam("utool", 1, 1, 10, "Tool frame",
                          "UTOOL_NUM of the torch TCP; it must be the TCP the kinematics used.", "Frames"));
  defs.push_back(
      choiceParam("position_format", "cartesian", {"cartesian", "joint"},
                  {"Positions",
                   "cartesian: XYZWPR with the CONFIG string. joint: the solved J1..J6 (needs a solved "
                   "cell), so the robot runs exactly the optimised joint motion (seed 004's production "
                   "mode); approach and retract stay Cartesian.",
                   "Frames"}));
  defs.push_back(textParam("default_config", "N U T, 0, 0, 0",
                           {"Default configuration",
                            "CONFIG string used when the plan has no solved cell: wrist N/F, elbow U/D, base "
                            "T/B, then the J1, J4, J6 turn numbers.",
                            "Frames"}));
  defs.push_back(
      intParam("cnt", 100, 0, 100, "Continuous termination",
               "CNT value of the path moves: 100 rounds each point most smoothly, 0 slows down to each "
               "one. The arc start and end points are always FINE.",
               "Motion"));
  defs.push_back(
      choiceParam("speed_unit", "auto", {"auto", "mm/sec", "cm/min", "msec"},
                  {"Speed unit",
                   "mm/sec and cm/min write the plan's travel speed rounded to whole units (cm/min is "
                   "six times finer); msec writes each move's planned duration, which also holds with a "
                   "moving positioner. auto: msec with a positioner (the table carries the part under a "
                   "torch that hardly moves, so a TCP speed would be meaningless), mm/sec otherwise.",
                   "Motion"}));
  defs.push_back(approachDistanceParam());
  defs.push_back(approachSpeedParam(2000.0));
  defs.push_back(jointSpeedParam());
  defs.push_back(processCommandParam());
  defs.push_back(intParam("weld_schedule", 1, 1, 99, "Weld schedule",
                          "ArcTool weld schedule of Arc Start[n], struck once at the first deposition point.",
                          "Process"));
  defs.push_back(intParam("end_schedule", 1, 1, 99, "End schedule",
                          "ArcTool schedule of Arc End[n] (crater fill), once at the last deposition point.",
                          "Process"));
  defs.push_back(intParam("wfs_output", 1, 1, 512, "WFS analog output",
                          "AO number that carries the wire-feed setpoint in the analog process modes.",
                          "Process"));
  const std::string counts = "FANUC analog outputs take the converter's integer count.";
  defs.push_back(wfsOffsetParam(-100000.0, 100000.0, counts));
  defs.push_back(wfsGainParam(100.0, -100000.0, 100000.0, counts));
  defs.push_back(wfsDeadbandParam());
  defs.push_back(forceParam());
  return ParamSchema(std::move(defs));
}

TpSpeedUnit speedUnit(const std::string& s)
{
  if (s == "cm/min") return TpSpeedUnit::CmPerMin;
  if (s == "msec") return TpSpeedUnit::Msec;
  return TpSpeedUnit::MmPerSec;
}

std::string percent(double fraction)
{
  std::string s;
  appendFixed(s, 100.0 * fraction, 1);
  return s + " %";
}

// Configurations from the cell must be valid TP strings; missing ones fall back to the default.
void checkConfigs(const ExportPath& path, const TpSettings& s, ExportResult& result)
{
  if (!isValidTpConfig(s.defaultConfig))
    throw InputError(
        "default_config '" + s.defaultConfig + "' is not a TP configuration",
        "write it as 'N U T, 0, 0, 0': wrist N or F, elbow U or D, base T or B, then three turns");
  if (!path.hasJoints) return;
  size_t missing = 0;
  for (size_t i = 0; i < path.points.size(); ++i) {
    const std::string& c = path.points[i].fanucConfig;
    if (c.empty()) {
      ++missing;
    } else if (!isValidTpConfig(c)) {
      throw InputError("the joint trajectory gives point " + std::to_string(i) + " the configuration '" + c +
                           "', which is not a TP configuration",
                       "solve the kinematics again for the FANUC cell");
    }
  }
  if (missing > 0)
    result.warnings.push_back(std::to_string(missing) + " points have no configuration from the cell; '" +
                              s.defaultConfig + "' was written for them");
}

}  // namespace

FanucTpExporter::FanucTpExporter() : schema_(makeSchema()) {}

std::string FanucTpExporter::description() const
{
  return "FANUC R-30iB ArcTool program: L moves with XYZWPR and CONFIG (or J1..J6) and a GP2 positioner, "
         "speeds per move from the plan's travel speed, one Arc Start and one Arc End, split into called "
         "parts when long.";
}

ExportResult FanucTpExporter::write(const ExportInput& input, const ParamSet& params,
                                    const std::filesystem::path& outDir, Progress& progress) const
{
  const auto [values, options] = startExport(schema_, params, outDir, "fanuc_r30ib");

  TpSettings s;
  s.programName = values.getString("program_name");
  s.maxPoints = static_cast<size_t>(values.getInt("max_points"));
  s.uframe = static_cast<int>(values.getInt("uframe"));
  s.utool = static_cast<int>(values.getInt("utool"));
  s.jointPositions = values.getString("position_format") == "joint";
  s.defaultConfig = values.getString("default_config");
  s.cnt = static_cast<int>(values.getInt("cnt"));
  const std::string unit = values.getString("speed_unit") != "auto"      ? values.getString("speed_unit")
                           : input.joints && input.joints->hasPositioner ? "msec"
                                                                         : "mm/sec";
  s.speedUnit = speedUnit(unit);
  s.approachSpeed = options.approachSpeed;
  s.jointSpeed = static_cast<int>(values.getInt("joint_speed"));
  s.process = options.process;
  s.weldSchedule = static_cast<int>(values.getInt("weld_schedule"));
  s.endSchedule = static_cast<int>(values.getInt("end_schedule"));
  s.wfsOutput = static_cast<int>(values.getInt("wfs_output"));
  s.wfsOffset = values.getDouble("wfs_offset");
  s.wfsGain = values.getDouble("wfs_gain");
  const auto date = input.header.find("date");
  if (date != input.header.end()) s.date = date->second;
  if (s.jointPositions && !input.joints)
    throw InputError("joint positions need a solved cell, and this plan has none",
                     "solve the cell's kinematics, or set position_format to cartesian");

  const ExportPath path = prepareExportPath(input, options, progress);
  ExportResult result;
  result.warnings = path.warnings;
  checkConfigs(path, s, result);
  const std::string name = tpProgramName(s.programName);
  if (name != s.programName)
    result.warnings.push_back("program name '" + s.programName +
                              "' is not a valid TP name (at most 36 capital "
                              "letters, digits or '_', starting with a letter); written as '" +
                              name + "'");

  std::vector<std::pair<std::string, std::string>> settings;
  settings.emplace_back("program", tpProgramName(s.programName));
  std::string length;
  appendFixed(length, path.length, 1);
  settings.emplace_back("points", std::to_string(path.points.size()) + ", path " + length + " mm");
  settings.emplace_back("frames",
                        "UFRAME " + std::to_string(s.uframe) + ", UTOOL " + std::to_string(s.utool));
  if (path.hasJoints) {
    settings.emplace_back("targets",
                          s.jointPositions ? "J1..J6 of the solved cell" : "TCP in World of the solved cell");
  } else {
    settings.emplace_back("targets", "TCP in the part frame, no cell");
    result.warnings.push_back(
        "no solved cell: the targets are torch poses in the part frame with the default configuration '" +
        s.defaultConfig + "'; measure the part frame as UFRAME " + std::to_string(s.uframe) +
        " and check the configuration before running");
  }
  if (path.hasPositioner) settings.emplace_back("positioner", "GP2, not coordinated");
  settings.emplace_back("speed", unit + ", CNT" + std::to_string(s.cnt));
  settings.emplace_back(
      "process", std::string(processCommandName(s.process)) + ", Arc Start[" +
                     std::to_string(s.weldSchedule) + "], Arc End[" + std::to_string(s.endSchedule) + "]" +
                     (s.process == ProcessCommand::Speed ? std::string()
                                                         : ", WFS AO[" + std::to_string(s.wfsOutput) + "]"));
  if (path.arcCount > 1)
    settings.emplace_back("sub-paths", std::to_string(path.arcCount) + " arcs, J travel between them");
  if (path.hasLead && s.process != ProcessCommand::Speed) settings.emplace_back("wfs lead", "TB point logic");
  if (path.flaggedCount > 0)
    settings.emplace_back("forced", std::to_string(path.flaggedCount) + " points flagged");
  const std::vector<std::string> header = programHeaderLines(input.header, settings);

  const TpOutput out = writeTpProgram(path, s, header, progress);
  // A move the controller would run at a speed far from the plan's lays another deposit height:
  // refused, with the unit that writes every move closely when there is one (written and checked).
  constexpr double kRefusedSpeedError = 0.5;
  if (out.worstSpeedError > kRefusedSpeedError) {
    std::string hint = "check the plan's travel speeds (the ts column of trajectory.csv)";
    if (s.speedUnit != TpSpeedUnit::Msec) {
      TpSettings msec = s;
      msec.speedUnit = TpSpeedUnit::Msec;
      NullProgress quiet;
      const TpOutput alt = writeTpProgram(path, msec, header, quiet);
      if (alt.worstSpeedError <= 0.05)
        hint = "set the speed unit to msec (--speed-unit msec), which writes every move within " +
               percent(alt.worstSpeedError) + " of its planned speed";
    }
    throw InputError("move " + std::to_string(out.worstSpeedMove) + " of the program is planned at " +
                         significantText(out.worstSpeedWanted, 3) + " mm/s, which whole " + unit +
                         " cannot write: the controller would run it " + percent(out.worstSpeedError) +
                         " off its planned speed",
                     hint);
  }
  if (out.worstSpeedError > 0.05)
    result.warnings.push_back("rounding to whole " + unit + " changes a move's speed by up to " +
                              percent(out.worstSpeedError) +
                              "; choose cm/min or msec for slow travel speeds");
  result.files = finishExport(outDir, out.files, progress);
  return result;
}

}  // namespace spira

void spira_register_export_fanuc_tp(spira::PluginRegistry& registry)
{
  registry.add(std::make_unique<spira::FanucTpExporter>());
}
