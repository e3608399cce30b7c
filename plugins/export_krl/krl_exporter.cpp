#include "krl_exporter.h"

#include <memory>

#include "krl_program.h"
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
  defs.push_back(programNameParam("spira_part",
                                  "KRL names: at most 24 letters, digits or '_', starting with a letter."));
  defs.push_back(maxPointsParam(
      5000, 100000, "Each part is a .src/.dat pair; smaller data lists load faster on the KR C4."));
  defs.push_back(intParam("tool", 1, 1, 16, "Tool number",
                          "TOOL_DATA index of the torch TCP; it must be the TCP the kinematics used.",
                          "Frames"));
  defs.push_back(
      intParam("base", 0, 0, 32, "Base number",
               "BASE_DATA index the targets refer to; 0 = $NULLFRAME. With a solved cell the targets "
               "are in the robot base frame, so use 0 (or a base equal to $ROBROOT); without one they "
               "are in the part frame, so use the base measured on the part.",
               "Frames"));
  defs.push_back(
      numberParam("c_dis", 0.5, 0.0, 50.0, "mm",
                  {"Approximation distance",
                   "$APO.CDIS: the robot rounds each point within this distance (LIN ... C_DIS) so the "
                   "path runs without stops. Keep it below half the point spacing. 0 stops at every "
                   "point.",
                   "Motion"}));
  defs.push_back(approachDistanceParam());
  defs.push_back(approachSpeedParam(2000.0));
  defs.push_back(jointSpeedParam());
  defs.push_back(processCommandParam());
  defs.push_back(intParam(
      "arc_output", 1, 1, 8192, "Arc-on output",
      "$OUT number that switches the arc (TRUE = arc on), set by path-synchronous triggers.", "Process"));
  defs.push_back(intParam("weld_job", 1, 0, 255, "Weld job",
                          "Job (synergic parameter set) selected on the job outputs before the first move.",
                          "Process"));
  defs.push_back(intParam("end_job", 0, 0, 255, "End job",
                          "Job selected on the job outputs where the arc is put out (crater fill), switched "
                          "with the arc-off trigger; 0 keeps the weld job.",
                          "Process"));
  defs.push_back(intParam("job_output", 0, 0, 8192, "First job output",
                          "First $OUT of the job-number outputs; 0 = the program selects no job (the power "
                          "source keeps its own).",
                          "Process"));
  defs.push_back(intParam("job_bits", 8, 1, 16, "Job outputs", "Number of outputs that carry the job number.",
                          "Process"));
  defs.push_back(intParam("wfs_output", 1, 1, 64, "WFS analog output",
                          "$ANOUT number that carries the wire-feed setpoint in the analog process modes.",
                          "Process"));
  defs.push_back(wfsOffsetParam(-1.0, 1.0, "KRL analog outputs run from -1.0 to 1.0 (+-10 V)."));
  defs.push_back(wfsGainParam(0.1, -1.0, 1.0, "KRL analog outputs run from -1.0 to 1.0 (+-10 V)."));
  defs.push_back(wfsDeadbandParam());
  defs.push_back(forceParam());
  return ParamSchema(std::move(defs));
}

std::string mmText(double x)
{
  std::string s;
  appendFixed(s, x, 3);
  return s;
}

}  // namespace

KrlExporter::KrlExporter() : schema_(makeSchema()) {}

std::string KrlExporter::description() const
{
  return "KUKA KR C4 program: LIN moves with E6POS targets (S/T and E1/E2 from the solved cell), $VEL.CP "
         "from the plan's travel speed, arc and wire feed on path-synchronous triggers, split into called "
         "parts when long.";
}

ExportResult KrlExporter::write(const ExportInput& input, const ParamSet& params,
                                const std::filesystem::path& outDir, Progress& progress) const
{
  const auto [values, options] = startExport(schema_, params, outDir, "kuka_krc4");
  const ExportPath path = prepareExportPath(input, options, progress);

  KrlSettings s;
  s.programName = values.getString("program_name");
  s.maxPoints = static_cast<size_t>(values.getInt("max_points"));
  s.tool = static_cast<int>(values.getInt("tool"));
  s.base = static_cast<int>(values.getInt("base"));
  s.cdis = values.internal(schema_, "c_dis");
  s.jointSpeed = static_cast<int>(values.getInt("joint_speed"));
  s.approachSpeed = options.approachSpeed;
  s.process = options.process;
  s.arcOutput = static_cast<int>(values.getInt("arc_output"));
  s.weldJob = static_cast<int>(values.getInt("weld_job"));
  s.endJob = static_cast<int>(values.getInt("end_job"));
  s.jobOutput = static_cast<int>(values.getInt("job_output"));
  s.jobBits = static_cast<int>(values.getInt("job_bits"));
  s.wfsOutput = static_cast<int>(values.getInt("wfs_output"));
  s.wfsOffset = values.getDouble("wfs_offset");
  s.wfsGain = values.getDouble("wfs_gain");

  ExportResult result;
  result.warnings = path.warnings;
  const std::string name = krlProgramName(s.programName);
  if (name != s.programName)
    result.warnings.push_back("program name '" + s.programName +
                              "' is not a valid KRL name (at most 24 letters, "
                              "digits or '_', starting with a letter, no keyword); written as '" +
                              name + "'");
  std::vector<std::pair<std::string, std::string>> settings;
  settings.emplace_back("program", krlProgramName(s.programName));
  settings.emplace_back("points",
                        std::to_string(path.points.size()) + ", path " + mmText(path.length) + " mm");
  settings.emplace_back("frames", "$TOOL=TOOL_DATA[" + std::to_string(s.tool) + "], " +
                                      (s.base > 0 ? "$BASE=BASE_DATA[" + std::to_string(s.base) + "]"
                                                  : std::string("$BASE=$NULLFRAME")));
  if (path.hasJoints) {
    settings.emplace_back("targets",
                          "torch TCP in the robot base frame ($ROBROOT) of the solved cell, with S/T");
  } else {
    settings.emplace_back("targets", "torch TCP in the part frame (no solved cell), no S/T");
    result.warnings.push_back(
        "no solved cell: the targets are torch poses in the part frame without S/T; measure the part frame "
        "as "
        "BASE_DATA[" +
        std::to_string(s.base) + "] and check the robot's configuration before running");
  }
  if (path.hasPositioner)
    settings.emplace_back("positioner",
                          "E1/E2 move with each LIN (not mathematically coupled); $VEL.CP keeps "
                          "each move's planned duration");
  settings.emplace_back("approximation",
                        s.cdis > 0.0 ? "C_DIS, $APO.CDIS " + mmText(s.cdis) + " mm" : "none");
  settings.emplace_back(
      "process",
      std::string(processCommandName(s.process)) + ", arc $OUT[" + std::to_string(s.arcOutput) + "]" +
          (s.process == ProcessCommand::Speed ? std::string()
                                              : ", WFS $ANOUT[" + std::to_string(s.wfsOutput) + "]") +
          (s.jobOutput > 0 ? ", job " + std::to_string(s.weldJob) : std::string()) +
          (s.jobOutput > 0 && s.endJob > 0 ? ", end job " + std::to_string(s.endJob) : std::string()));
  if (path.arcCount > 1)
    settings.emplace_back("sub-paths", std::to_string(path.arcCount) +
                                           " arcs, one per sub-path; PTP travel between them, arc off");
  if (path.hasLead && s.process != ProcessCommand::Speed)
    settings.emplace_back("wfs lead", "setpoints led by the feeder's lag (TRIGGER DELAY)");
  if (path.flaggedCount > 0)
    settings.emplace_back("forced",
                          std::to_string(path.flaggedCount) + " points flagged, see WARNING comments");
  const std::vector<std::string> header = programHeaderLines(input.header, settings);

  const std::vector<OutputFile> files = writeKrlProgram(path, s, header, progress);
  result.files = finishExport(outDir, files, progress);
  return result;
}

}  // namespace spira

void spira_register_export_krl(spira::PluginRegistry& registry)
{
  registry.add(std::make_unique<spira::KrlExporter>());
}
