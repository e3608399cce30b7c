#include "gcode_exporter.h"

#include <map>
#include <memory>

#include "gcode_machine.h"
#include "gcode_program.h"
#include "head_kinematics.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/export/export_params.h"
#include "spira/export/export_steps.h"
#include "spira/export/fixed_number.h"
#include "spira/export/program_header.h"
#include "spira/export/program_names.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {

namespace {

ParamSchema makeSchema()
{
  std::vector<ParamDef> defs;
  defs.push_back(
      pathParam("machine", {"Machine file",
                            "The .machine file of the gantry and its tilting head: axis letters, rotary axes "
                            "and offsets, limits, feeds and the process codes (docs/machine-format.md; "
                            "resources/machines/ has an example).",
                            "Machine"}));
  defs.push_back(numberParam(
      "upright_tolerance", 0.0, 0.0, 5.0, "deg",
      {"Upright tolerance",
       "A torch axis leaning less than this from the head's zero direction is written at zero tilt, the "
       "turning axis kept where it is. A spiral's slight lean (its pitch) would otherwise turn that axis "
       "once per revolution; 0 follows the plan exactly.",
       "Machine"}));
  defs.push_back(
      textParam("program_name", "spira_part",
                {"Program name",
                 "Name of the program file (NAME.nc): letters, digits and '_', at most 32, starting "
                 "with a letter; other characters become '_'.",
                 "Program"}));
  defs.push_back(intParam("program_number", 1000, 0, 9999, "Program number",
                          "The O-word of the program (O1000); 0 writes none.", "Program"));
  defs.push_back(intParam("decimals", 3, 1, 6, "Decimal places",
                          "Places of the axis words (mm, deg) and of the wire-feed value.", "Program"));
  defs.push_back(flagParam(
      "line_numbers", false,
      {"Line numbers", "Number every block N1, N2... (comments and % are not numbered).", "Program"}));
  defs.push_back(choiceParam(
      "feed_mode", "mm_per_min", {"mm_per_min", "inverse_time"},
      {"Feed mode",
       "mm_per_min (G94): F is the plan's travel speed of the tool tip, for a controller with tool-tip "
       "control. inverse_time (G93): F is 1 / each move's planned duration in minutes, so a controller "
       "without it still runs every move in the planned time while the head turns.",
       "Motion"}));
  defs.push_back(approachDistanceParam());
  defs.push_back(approachSpeedParam(1000.0));
  defs.push_back(wfsDeadbandParam());
  return ParamSchema(std::move(defs));
}

const ProgramNameRules& gcodeNameRules()
{
  static const ProgramNameRules rules{32, false, "spira_part", {}};
  return rules;
}

std::string pointName(const ExportPath& path, size_t i)
{
  if (path.hasApproach) {
    if (i == 0) return "the approach";
    if (i == path.points.size() + 1) return "the retract";
    --i;
  }
  return "program point " + std::to_string(i);
}

void checkFeeds(const ExportPath& path, const GcodeMachine& m, double approachFeed)
{
  if (approachFeed > m.maxFeed)
    throw InputError("the approach speed (" + roundedText(approachFeed, 1) +
                         " mm/min) is above the machine's " + "max_mm_per_min " + roundedText(m.maxFeed, 1),
                     "lower --approach-speed");
  for (size_t i = 1; i < path.points.size(); ++i) {
    const double f = path.points[i].speed * 60.0;
    if (f > m.maxFeed * (1.0 + 1e-9))
      throw InputError("program point " + std::to_string(i) + " is planned at " + roundedText(f, 1) +
                           " mm/min, above the machine's max_mm_per_min " + roundedText(m.maxFeed, 1),
                       "lower the plan's travel speed, or raise max_mm_per_min in the machine file if the "
                       "machine allows it");
  }
}

}  // namespace

GcodeExporter::GcodeExporter() : schema_(makeSchema()) {}

std::string GcodeExporter::description() const
{
  return "G-code for a gantry or CNC WAAM machine with a tilting head: the head's axes solved from the torch "
         "poses, G1 moves with the plan's feed, the wire feed and arc on/off as the machine file's codes.";
}

ExportResult GcodeExporter::write(const ExportInput& input, const ParamSet& params,
                                  const std::filesystem::path& outDir, Progress& progress) const
{
  const ParamSet values = params.withDefaults(schema_);
  schema_.validate(values);
  const std::string machineFile = values.getString("machine");
  if (machineFile.empty())
    throw InputError("the G-code export needs a machine file",
                     "give --machine FILE, e.g. --machine "
                     "resources/machines/gantry_ca_head.machine");
  ensureWritableDirectory(outDir);
  const GcodeMachine machine = readMachineFile(machineFile);

  PathOptions options;
  options.controller = "gcode";
  options.approachDistance = values.internal(schema_, "approach_distance");
  options.approachSpeed = values.internal(schema_, "approach_speed");
  // The wire feed is always commanded: the machine has no weld job that would set it.
  options.process = ProcessCommand::SpeedAnalog;
  options.wfsDeadband = values.internal(schema_, "wfs_deadband");
  const ExportPath path = prepareExportPath(input, options, progress);
  if (path.hasJoints)
    throw InputError("the G-code export got a robot's joint trajectory",
                     "export without a cell: the machine file replaces it");

  GcodeSettings s;
  s.decimals = static_cast<int>(values.getInt("decimals"));
  s.lineNumbers = values.getBool("line_numbers");
  s.programNumber = static_cast<int>(values.getInt("program_number"));
  s.approachFeed = options.approachSpeed * 60.0;
  s.inverseTime = values.getString("feed_mode") == "inverse_time";
  checkFeeds(path, machine, s.approachFeed);

  std::vector<HeadPose> poses;
  poses.reserve(path.points.size() + 2);
  auto add = [&poses](const Transform& t) { poses.push_back({t.translation(), t.linear().col(2)}); };
  if (path.hasApproach) add(path.approach);
  for (const ExportPoint& p : path.points) add(p.pose);
  if (path.hasApproach) add(path.retract);
  const std::vector<HeadAxes> axes = solveHeadPath(
      machine, poses, [&path](size_t i) { return pointName(path, i); },
      values.getDouble("upright_tolerance"));
  GcodeTargets targets;
  const size_t first = path.hasApproach ? 1 : 0;
  targets.points.assign(axes.begin() + static_cast<std::ptrdiff_t>(first),
                        axes.begin() + static_cast<std::ptrdiff_t>(first + path.points.size()));
  if (path.hasApproach) {
    targets.approach = axes.front();
    targets.retract = axes.back();
  }

  ExportResult result;
  result.warnings = path.warnings;
  const std::string wanted = values.getString("program_name");
  const std::string name = sanitizeProgramName(wanted, gcodeNameRules());
  if (name != wanted) result.warnings.push_back("program name '" + wanted + "' written as '" + name + "'");

  std::vector<std::pair<std::string, std::string>> settings;
  settings.emplace_back("program", name);
  settings.emplace_back("machine", (machine.name.empty() ? std::string() : machine.name + ", ") +
                                       std::filesystem::path(machineFile).filename().string());
  std::string length;
  appendFixed(length, path.length, 1);
  settings.emplace_back("points", std::to_string(path.points.size()) + ", path " + length + " mm");
  settings.emplace_back(
      "targets", "machine coordinates, part origin at X" + roundedText(machine.partOrigin.x(), 3) + " Y" +
                     roundedText(machine.partOrigin.y(), 3) + " Z" + roundedText(machine.partOrigin.z(), 3));
  settings.emplace_back("feed", std::string(s.inverseTime ? "inverse time, G93" : "mm/min, G94") +
                                    "; wire feed " + machine.wireFeedUnit);
  if (path.arcCount > 1) settings.emplace_back("sub-paths", std::to_string(path.arcCount) + " arcs");
  // The machine file stands for the cell, whatever cell the plan was made with.
  std::map<std::string, std::string> names = input.header;
  names.erase("cell");
  const std::vector<std::string> header = programHeaderLines(names, settings);

  std::vector<OutputFile> files;
  files.push_back({name + ".nc", writeGcodeProgram(path, targets, machine, s, header, progress), false});
  result.files = finishExport(outDir, files, progress);
  return result;
}

}  // namespace spira

void spira_register_export_gcode(spira::PluginRegistry& registry)
{
  registry.add(std::make_unique<spira::GcodeExporter>());
}
