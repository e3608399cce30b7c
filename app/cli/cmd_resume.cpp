// spira-cli resume: the rest of a build re-planned from a scan of the wall as it stands; and the
// simulated scan of a plan built part way with a deposit error (scan-sim PLAN_DIR).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "plan_folder.h"
#include "quality_outputs.h"
#include "robot_output.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/base/output_set.h"
#include "spira/document/plan_report.h"
#include "spira/pipeline/export_job.h"
#include "spira/pipeline/prep_schema.h"
#include "spira/pipeline/program_header.h"
#include "spira/planning/plan_files.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
#include "spira/scan/scan_reader.h"
#include "spira/scan/scan_resume.h"
#include "spira/scan/scan_writer.h"

namespace fs = std::filesystem;

namespace spira::cli {
namespace {

constexpr const char* kResumeHelp =
    "usage: spira-cli resume PLAN_DIR --scan SCAN --at INDEX -o DIR [--bead-width MM]\n"
    "                        [--export krl|fanuc_tp|rapid [exporter flags]]\n\n"
    "Re-plans the rest of the build of PLAN_DIR (written by 'spira-cli plan') from a scan of the\n"
    "wall as it stands after INDEX points were deposited. The scan (in the part's frame: align one\n"
    "taken elsewhere with scan-compare first) gives the top of the last bead on each generatrix;\n"
    "what it lacks of the plan (or has too much) is made up by laying the next revolutions thicker\n"
    "(or thinner) inside the plan's window, over the fewest revolutions that allows, the torch\n"
    "following the wall as it stands. Writes DIR/trajectory.csv (the points from INDEX on: the arc\n"
    "restarts at the first) and DIR/report.json (the measured edge and its process index, the\n"
    "revolutions taken, the deposits, whether the planned top is reached). With --export, the\n"
    "continuation's robot program on the plan's cell (report.json's cell_file), one arc from the\n"
    "restart point. Exit 4 when the window cannot make the difference up (the report says by how\n"
    "much and where; no program is written), 3 for a scan or index that does not fit.\n";

// "uniform:-8%", "sag:-8%@30%,-y": the relative error, until which share of the plan, and for a sag the
// side (x, -x, y, -y).
DepositErrors errorFlag(const std::string& text)
{
  const std::string example = "--error uniform:-8%@30% or --error sag:-8%@30%,-y";
  const size_t colon = text.find(':');
  if (text.empty() || colon == std::string::npos)
    throw UsageError("--error '" + text + "' names no error", "give " + example);
  DepositErrors e;
  const std::string kind = text.substr(0, colon);
  if (kind == "sag")
    e.kind = DepositErrors::Kind::Sag;
  else if (kind != "uniform")
    throw UsageError("--error kind '" + kind + "' is not uniform or sag", "give " + example);
  std::string rest = text.substr(colon + 1);
  const size_t comma = rest.find(',');
  if (comma != std::string::npos) {
    const std::string side = rest.substr(comma + 1);
    rest = rest.substr(0, comma);
    if (side == "x")
      e.side = Vec3::UnitX();
    else if (side == "-x")
      e.side = -Vec3::UnitX();
    else if (side == "y")
      e.side = Vec3::UnitY();
    else if (side == "-y")
      e.side = -Vec3::UnitY();
    else
      throw UsageError("--error side '" + side + "' is not x, -x, y or -y", "give " + example);
  }
  const auto percent = [&](std::string p) {
    if (p.empty() || p.back() != '%')
      throw UsageError("--error '" + text + "': '" + p + "' is not a percentage", "give " + example);
    p.pop_back();
    return finiteNumberFlag("--error", p, example) / 100.0;
  };
  const size_t atSign = rest.find('@');
  e.relative = percent(rest.substr(0, atSign));
  if (atSign != std::string::npos) e.until = percent(rest.substr(atSign + 1));
  if (e.relative <= -1.0 || e.until <= 0.0 || e.until > 1.0)
    throw UsageError("--error '" + text + "' is out of range",
                     "give an error above -100 % until 1 to 100 % of the plan");
  return e;
}

}  // namespace

int simulatePlanScan(Args& args, const std::string& planDir, const fs::path& out, double noiseMm,
                     long long seed)
{
  const PlanFolder plan = readPlanFolder(planDir);
  const size_t at = atFlag(args.takeOption("--at"), plan.trajectory);
  const DepositErrors errors = errorFlag(args.takeOption("--error"));
  const double beadWidth = beadWidthFlag(args.takeOption("--bead-width"));
  args.finish("scan-sim", 1, 1);
  const std::vector<double> shortfall = builtShortfall(plan.trajectory, at, errors);
  const PointCloud scan = scanOfBuild(plan.trajectory, at, shortfall, beadWidth, 3, 2.0 * beadWidth, noiseMm,
                                      std::uint64_t(seed));
  writeFileAtomically(out, pointCloudPly(scan));
  double deepest = 0.0;
  for (double s : shortfall) deepest = std::max(deepest, s);
  std::cout << "wrote " << out.string() << ": " << scan.size() << " points of the wall built to point " << at
            << ", its top up to " << significantText(deepest, 3) << " mm below the plan\n";
  return kExitOk;
}

int cmdResume(const std::vector<std::string>& argv)
{
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout << kResumeHelp;
    return kExitOk;
  }
  const std::string scanFile = args.takeOption("--scan");
  const std::string atText = args.takeOption("--at");
  const std::string outText = args.takeOption("-o");
  const double beadWidth = beadWidthFlag(args.takeOption("--bead-width"));
  const std::string format = args.takeOption("--export");
  const PluginRegistry& registry = builtinRegistry();
  const ExporterPlugin* exporter = format.empty() ? nullptr : &exporterFor(registry, format);
  ParamSet exporterValues, prepValues;
  if (exporter)
    args.rest =
        takeParamFlags(args.rest, {FlagTarget{exporter->id(), &exporter->schema(), &exporterValues},
                                   FlagTarget{std::string(prepSection().name), &prepSchema(), &prepValues}});
  const auto positional = args.finish("resume", 1, 1);
  if (scanFile.empty())
    throw UsageError("resume needs --scan SCAN", "give the scan of the wall as it stands");
  if (outText.empty()) throw UsageError("resume needs -o DIR", "add -o DIR for the continuation");
  const fs::path outDir(outText);
  ensureWritableDirectory(outDir);
  const PlanFolder plan = readPlanFolder(positional[0]);
  const size_t at = atFlag(atText, plan.trajectory);
  if (at >= plan.trajectory.size())
    throw InputError("--at " + atText + ": the plan has " + std::to_string(plan.trajectory.size()) +
                         " points, all deposited; nothing is left to resume",
                     "give fewer points than the plan has");
  if (!plan.report.window)
    throw InputError("'" + positional[0] + "/report.json' holds no process window (h_min, h_max)",
                     "plan the part again with 'spira-cli plan'");
  std::optional<RobotCell> cell;
  if (exporter && !plan.report.cellFile.empty()) {
    cell.emplace(readCellFile(plan.report.cellFile));
    if (!cell->canSolve()) throw InputError(cell->ikRefusal(), "choose a cell with a 6-axis arm");
  }
  if (exporter && !cell)
    std::cerr << "note: the plan names no cell: the program's targets are torch poses in the part frame\n";
  NullProgress progress;
  const PointCloud scan = readScan(builtinRegistry(), scanFile, progress);
  const MeasuredEdge edge = measureTopEdge(plan.trajectory, at, scan, beadWidth);
  ResumeSettings settings;
  settings.hMin = plan.report.window->hMin;
  settings.hMax = plan.report.window->hMax;
  settings.process = processOfPlan(plan.trajectory, beadWidth);
  const Resumed resumed = resumeFromEdge(plan.trajectory, at, edge, settings);
  const ResumeReport& r = resumed.report;

  nlohmann::json j;
  j["resumed_from"] = fs::absolute(positional[0]).lexically_normal().string();
  j["scan"] = scanFile;
  j["at"] = at;
  j["n_points"] = resumed.continuation.size();
  j["h_min"] = settings.hMin;
  j["h_max"] = settings.hMax;
  j["edge"] = {{"points", r.edgePoints},
               {"unmeasured", r.unmeasured},
               {"shortfall_min_mm", r.shortfallMin},
               {"shortfall_max_mm", r.shortfallMax},
               {"shortfall_mean_mm", r.shortfallMean}};
  j["revolutions_to_make_up"] = r.revolutionsMax;
  j["height_min"] = r.heightMin;
  j["height_max"] = r.heightMax;
  j["reaches_top"] = r.reachesTop();
  j["leftover_mm"] = r.leftoverMax;
  if (!r.reachesTop()) j["leftover_point"] = r.leftoverPoint;
  const IndexStats process = indexStats(processIndex(plan.trajectory, edge));
  j["process_index"] = indexStatsJson(process);
  j["summary"] = r.summary();
  replaceOutputSet(
      outDir, OutputKind::Plan,
      {{"trajectory.csv", trajectoryCsv(resumed.continuation)}, {"report.json", j.dump(2) + "\n"}});
  std::cout << "resume from point " << at << ": " << r.summary() << "\n";
  std::cout << "process index of the wall as built (1 = as planned): mean "
            << significantText(process.mean, 4) << ", min " << significantText(process.min, 4) << "\n";
  std::cout << "wrote " << (outDir / "trajectory.csv").string() << " (" << resumed.continuation.size()
            << " points, the arc restarting at the first) and report.json\n";
  if (exporter && !r.reachesTop())
    std::cout << "the robot program was not written: the continuation does not reach the planned top\n";
  if (exporter && r.reachesTop()) {
    ExportJob job;
    job.exporterId = exporter->id();
    job.exporterParams = exporterValues;
    job.prep = prepParamsFrom(prepValues);
    job.cell = cell ? &*cell : nullptr;
    job.positionerToleranceDeg = plan.report.positionerToleranceDeg;
    job.header = programHeader(positional[0], plan.report.cellFile, plan.report);
    printExportSummary(exportTrajectory(registry, resumed.continuation, job, outDir, progress), std::cout);
  }
  return r.reachesTop() ? kExitOk : kExitInfeasible;
}

}  // namespace spira::cli
