#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "part_plan.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/base/output_set.h"
#include "spira/base/progress.h"
#include "spira/document/document.h"
#include "spira/document/plan_report.h"
#include "spira/document/project_file.h"
#include "spira/document/stage_report_codec.h"
#include "spira/pipeline/plan_records.h"
#include "spira/pipeline/planned_path.h"
#include "spira/planning/plan_files.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/trajectory_csv_reader.h"
#include "spira/thermal/thermal_replan.h"
#include "spira/thermal/thermal_study.h"
#include "spira/thermal/thermal_substrate.h"
#include "spira/thermal/thermal_vtk.h"
#include "spira/verify/deposit_check.h"
#include "thermal_backend.h"
#include "thermal_outputs.h"

namespace fs = std::filesystem;

namespace spira::cli {
namespace {

constexpr double kDefaultEfficiency = 0.8;  // GMAW/CMT arc efficiency, DuPont & Marder 1995: 0.8-0.85

// What the thermal model runs on: a planned path with its process channels.
struct ThermalSource {
  Trajectory trajectory;
  std::optional<double> beadWidth;  // mm, from a project's process settings
  ProcessLimits limits;             // a project's, else the product's defaults
  nlohmann::json report;            // the plan's report.json, for a re-planned one
};

ThermalSource readSource(const fs::path& input)
{
  ThermalSource s;
  if (fs::is_directory(input)) {
    verifyOutputSet(input);
    s.trajectory = readTrajectoryCsv(input / "trajectory.csv");
    if (fs::exists(input / "report.json"))
      s.report = nlohmann::json::parse(readFile(input / "report.json"), nullptr, false);
    if (s.report.is_discarded()) s.report = nlohmann::json::object();
    return s;
  }
  Document doc;
  doc.open(input);
  const PlannedPath planned = plannedPathOf(doc.results());
  if (!planned.trajectory || planned.trajectory->empty())
    throw InputError("the project '" + input.string() + "' holds no planned trajectory",
                     "plan it first (Plan in Spira, or spira-cli plan PROJECT --save), then simulate it");
  s.trajectory = *planned.trajectory;
  const ProcessSettings process = readPlanSections(doc.settings()->params).process;
  s.beadWidth = process.beadWidth;
  s.limits = process.limits;
  s.report = mergedPlanReport(doc.results());
  return s;
}

Vec3 probeFlag(const std::string& text)
{
  std::vector<double> v;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) v.push_back(finiteNumberFlag("--probe", item, "--probe 40,0,12.5"));
  if (v.size() != 3)
    throw UsageError("--probe needs three coordinates, found '" + text + "'", "write --probe X,Y,Z (mm)");
  return Vec3(v[0], v[1], v[2]);
}

double positiveValue(const std::string& flag, const std::string& text, const std::string& unit)
{
  const double v = finiteNumberFlag(flag, text, flag + " 1000");
  if (v <= 0.0)
    throw InputError(flag + " " + text + " " + unit + " is not positive",
                     "give a positive " + flag.substr(2) + " in " + unit);
  return v;
}

// The arc power of --power or --voltage/--current/--efficiency; none of them may be given with
// --energy-per-wire (`perWire`).
double arcPowerFrom(Args& args, bool perWire)
{
  const std::string power = args.takeOption("--power"), voltage = args.takeOption("--voltage"),
                    current = args.takeOption("--current"), efficiency = args.takeOption("--efficiency");
  if (perWire && (!power.empty() || !voltage.empty() || !current.empty() || !efficiency.empty()))
    throw UsageError("--energy-per-wire and --power/--voltage/--current both give the arc power",
                     "give --power W, --voltage V --current A [--efficiency E], or --energy-per-wire J");
  if (!power.empty() && (!voltage.empty() || !current.empty() || !efficiency.empty()))
    throw UsageError("--power and --voltage/--current/--efficiency both give the arc power",
                     "give --power W, or --voltage V --current A [--efficiency E]");
  if (!power.empty()) return positiveValue("--power", power, "W");
  if (voltage.empty() != current.empty())
    throw UsageError("the arc power needs both --voltage and --current", "write --voltage 18 --current 120");
  if (voltage.empty()) return 1000.0;  // the source's base case (000_dbb97c2716e10cc3.txt, section 5.6)
  return arcPower(finiteNumberFlag("--voltage", voltage, "--voltage 18"),
                  finiteNumberFlag("--current", current, "--current 120"),
                  efficiency.empty() ? kDefaultEfficiency
                                     : finiteNumberFlag("--efficiency", efficiency, "--efficiency 0.8"));
}

constexpr const char* kHelp =
    "usage: spira-cli thermal PLAN_DIR|PROJECT.spira|PART [plan flags] -o DIR [--material NAME]\n"
    "                         [--power W | --voltage V --current A [--efficiency E] |\n"
    "                         --energy-per-wire J | --power-table F] [--dt auto|S] [--probe X,Y,Z]...\n"
    "                         [--sub-segments K] [--divisions F] [--bead-width MM] [--substrate-z Z]\n"
    "                         [--source-radius R] [--emissivity E]\n"
    "                         [--scheme crank-nicolson|implicit-euler] [--cooling S] [--frames N]\n"
    "                         [--interpass-max C [--remedy deposit|heat|dwell[,...]] [--max-dwell S]]\n"
    "                         [--timing]\n"
    "                         [--backend eigen|petsc]\n\n"
    "Simulates the heat of the build along the planned path (docs/thermal.md): a shell of the deposit\n"
    "as thick as the bead, born where the torch lays it, heated by the moving arc,\n"
    "cooled by the air on both faces and by the substrate. Writes DIR/thermal.json (energy in, stored\n"
    "and lost, the highest peak and interpass temperatures, nodes, steps, times), DIR/thermal_points.csv\n"
    "(per planned point: peak, interpass - the lowest the deposit below it cooled to before the torch\n"
    "came back -, the temperature below at the torch's arrival, the time above melting) and\n"
    "DIR/probes.csv (temperature against time at each --probe, the nearest node), and the field over\n"
    "time as a ParaView series, DIR/thermal.pvd with DIR/thermal_NNNN.vtu.\n"
    "With --interpass-max, re-plans the path until no interpass temperature exceeds the limit and\n"
    "writes the re-planned DIR/trajectory.csv and DIR/report.json with the thermal files, as one set.\n"
    "A PART file (mesh or CAD) is planned first as 'spira-cli plan' plans it, with its flags (below);\n"
    "its trajectory.csv and report.json are written with the thermal files.\n\n"
    "  --material NAME   G3Si1 (default, the source's steel), 316L, Ti-6Al-4V, AlMg5\n"
    "  --power W         arc power reaching the part (default 1000 W, the source's base case), or\n"
    "  --voltage V --current A [--efficiency E]   its product (E default 0.8), or\n"
    "  --energy-per-wire J   the arc's energy per mm of wire fed (a synergic line): the power follows\n"
    "                    the wire feed point by point, or\n"
    "  --power-table F   a measured calibration, a CSV of wfs_m_min,power_W rows (header first):\n"
    "                    the power interpolated at each point's wire feed\n"
    "  --dt auto|S       time step; auto (default) moves the torch one sub-segment per step\n"
    "  --sub-segments K  mesh sub-segments per planned segment (default 1); --divisions F across a layer\n"
    "  --bead-width MM   shell thickness (default: the project's bead width, else 5.2 mm)\n"
    "  --substrate-z Z   the plate's plane (default: under the first revolution, its deposit height down)\n"
    "  --source-radius R the arc as a Gaussian flux of radius R, mm (default half the bead width);\n"
    "                    0: the source's point load (peaks and pool then depend on the mesh)\n"
    "  --cooling S       seconds simulated after the arc stops (default 0)\n"
    "  --emissivity E    radiation from both faces of the laid wall, E in [0, 1] (default 0: none,\n"
    "                    the source's model)\n"
    "  --frames N        frames of the field in the ParaView series (default 50; 0: none)\n"
    "  --interpass-max C the highest interpass temperature allowed, C\n"
    "  --remedy LIST     how to re-plan, one or more of (default heat), applied in this order:\n"
    "                    deposit: the overheating band laid with more, thinner revolutions (faster at\n"
    "                    a synergic wire feed, less wire at a constant travel speed), no thinner than\n"
    "                    the plan's h_min, kept only if the simulation finds it cooler; one spiral still\n"
    "                    heat: the wire feed and the travel speed slowed together there (same deposit,\n"
    "                    same spiral, less power; down to the process's slowest speeds)\n"
    "                    dwell: the torch stops before each revolution above the limit, lifts away with\n"
    "                    the arc off and waits; each dwell adds an arc start\n"
    "                    the arc power follows the wire feed when re-planning\n"
    "  --max-dwell S     the longest single dwell (default 600 s)\n"
    "  --backend NAME    linear solves in this process (eigen, default) or on PETSc (petsc), also across\n"
    "                    processes: mpirun -n N spira-cli thermal ... --backend petsc (rank 0 writes)\n"
    "Exit codes: 0 done, 2 usage, 3 bad input (unknown material, non-positive power, a time step too long\n"
    "for the torch, a plan without process channels, petsc or mpirun in a build without PETSc), 4 the\n"
    "interpass limit cannot be met (the best re-planned path and its thermal files are still written, to\n"
    "inspect) or the planned PART is not feasible.\n\n"
    "Plan flags, for a PART:\n"
    "  --strategy NAME    the decomposition (default isovalue); --no-mid-surface refuses a solid\n";

}  // namespace

// --power-table FILE: a CSV of wfs_m_min,power_W rows (a header line first), the arc's calibration.
std::vector<std::array<double, 2>> readPowerTable(const fs::path& file)
{
  if (!fs::is_regular_file(file))
    throw InputError("the power table '" + file.string() + "' does not exist",
                     "give a CSV file of wfs_m_min,power_W rows");
  std::istringstream in(readFile(file));
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::array<double, 2>> table;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream row(line);
    std::string wfs, power;
    std::getline(row, wfs, ',');
    std::getline(row, power);
    char* end1 = nullptr;
    char* end2 = nullptr;
    const double w = std::strtod(wfs.c_str(), &end1), p = std::strtod(power.c_str(), &end2);
    if (wfs.empty() || power.empty() || end1 == wfs.c_str() || end2 == power.c_str() ||
        std::string(end2).find_first_not_of(" \t\r") != std::string::npos)
      throw InputError(
          "line " + std::to_string(number) + " of '" + file.string() + "' is not two numbers: '" + line + "'",
          "each line after the header: wire feed in m/min, arc power in W, e.g. 2.3,1000");
    table.push_back({w * 1000.0 / 60.0, p});
  }
  try {
    validatePowerTable(table);
  } catch (const InputError& e) {
    throw InputError("'" + file.string() + "': " + e.what(), e.hint());
  }
  return table;
}

// Whether the command names a part file: no plan folder and no project among its arguments (the
// flags' values are numbers and names, never folders).
bool isPartInput(const std::vector<std::string>& rest)
{
  for (const std::string& a : rest) {
    std::error_code ec;
    if (fs::is_directory(a, ec) || fs::path(a).extension() == kProjectExtension) return false;
  }
  for (const std::string& a : rest) {
    std::error_code ec;
    if (a.rfind("-", 0) != 0 && fs::is_regular_file(a, ec)) return true;
  }
  return false;
}

// --remedy: a comma-separated list of the remedies to re-plan with, each at most once.
void takeRemedies(const std::string& text, ThermalReplanSettings& replan)
{
  replan.heat = false;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    bool* chosen = item == "deposit" ? &replan.deposit
                   : item == "heat"  ? &replan.heat
                   : item == "dwell" ? &replan.dwell
                                     : nullptr;
    if (!chosen)
      throw UsageError("--remedy " + item + " is not a remedy",
                       "write one or more of deposit, heat and dwell, e.g. --remedy deposit,heat");
    if (*chosen) throw UsageError("--remedy names " + item + " twice", "name each remedy once");
    *chosen = true;
  }
  if (!replan.deposit && !replan.heat && !replan.dwell)
    throw UsageError("--remedy names no remedy", "write --remedy heat, or deposit,heat,dwell");
}

// The deposit check of a path the deposit remedy thinned, judged on its own as a plan is: the plan's
// window, the shell's bead width, the substrate plane.
DepositCheckReport checkThinned(const ThermalReplanOutcome& outcome, const nlohmann::json& report,
                                const ThermalMeshSettings& mesh)
{
  DepositCheckSettings s;
  s.substrateZ = mesh.substrateZ;
  s.beadWidth = mesh.thickness;
  if (report.is_object()) {
    s.hMin = report.value("h_min", s.hMin);
    s.hMax = report.value("h_max", s.hMax);
    s.tolerance = report.value("height_tolerance_mm", s.tolerance);
  }
  NullProgress progress;
  return checkDeposits(outcome.trajectory, nullptr, s, progress);
}

void printStudy(const ThermalStudy& thermal, const ThermalSettings& settings, const nlohmann::json& report)
{
  const ThermalResult& result = thermal.result;
  std::cout << "thermal: " << result.nodes << " nodes, " << result.steps << " steps, "
            << significantText(result.simulatedTime, 4) << " s of build simulated in "
            << significantText(result.seconds, 3) << " s\n"
            << "peak " << significantText(report["max_peak_C"].get<double>(), 4) << " C, interpass up to "
            << significantText(report["max_interpass_C"].get<double>(), 4) << " C (" << settings.material.name
            << " melts at " << significantText(settings.material.meltingTemperature, 4) << " C), "
            << thermal.riskPoints << " point(s) at risk of collapse\n"
            << "energy: in " << significantText(result.energy.in, 4) << " J, stored "
            << significantText(result.energy.stored, 4) << " J, lost "
            << significantText(result.energy.lost, 4) << " J\n";
}

int cmdThermal(const std::vector<std::string>& argv)
{
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    const PartPlanFlags flags(builtinRegistry());
    std::cout << kHelp << kPlacementHelp << paramFlagsHelp(flags.targets());
    return kExitOk;
  }
  ThermalBackend backend(args);  // first, so that under mpirun only rank 0 reports what is wrong
  const bool timing = args.takeSwitch("--timing");
  const std::string outDir = args.takeOption("-o");
  ThermalStudySettings study;
  ThermalSettings& settings = study.solver;
  ThermalMeshSettings& mesh = study.mesh;
  if (const std::string name = args.takeOption("--material"); !name.empty())
    settings.material = thermalMaterialPreset(name);
  if (const std::string e = args.takeOption("--emissivity"); !e.empty()) {
    settings.material.emissivity = finiteNumberFlag("--emissivity", e, "--emissivity 0.8");
    validateThermalMaterial(settings.material);
  }
  const std::string perWire = args.takeOption("--energy-per-wire"), table = args.takeOption("--power-table");
  if (!perWire.empty() && !table.empty())
    throw UsageError("--energy-per-wire and --power-table both give the arc power", "give one of them");
  settings.power = arcPowerFrom(args, !perWire.empty() || !table.empty());
  if (!perWire.empty()) settings.powerPerWireFeed = positiveValue("--energy-per-wire", perWire, "J/mm");
  if (!table.empty()) settings.powerTable = readPowerTable(table);
  if (const std::string dt = args.takeOption("--dt"); !dt.empty() && dt != "auto")
    settings.timeStep = positiveValue("--dt", dt, "s");
  for (std::string p = args.takeOption("--probe"); !p.empty(); p = args.takeOption("--probe"))
    settings.probePositions.push_back(probeFlag(p));
  if (const std::string k = args.takeOption("--sub-segments"); !k.empty())
    mesh.subSegments = static_cast<int>(wholeNumberFlag("--sub-segments", k, 1, 64, "--sub-segments 2"));
  if (const std::string f = args.takeOption("--divisions"); !f.empty())
    mesh.divisions = static_cast<int>(wholeNumberFlag("--divisions", f, 1, 16, "--divisions 2"));
  const std::string beadWidth = args.takeOption("--bead-width"),
                    substrateZ = args.takeOption("--substrate-z"),
                    radius = args.takeOption("--source-radius");
  if (const std::string scheme = args.takeOption("--scheme"); !scheme.empty()) {
    if (scheme == "implicit-euler")
      settings.scheme = ThermalScheme::ImplicitEuler;
    else if (scheme != "crank-nicolson")
      throw UsageError("--scheme " + scheme + " is not a time scheme",
                       "write --scheme crank-nicolson or --scheme implicit-euler");
  }
  if (const std::string cooling = args.takeOption("--cooling"); !cooling.empty())
    settings.coolingTime = finiteNumberFlag("--cooling", cooling, "--cooling 600");
  study.frames = 50;
  if (const std::string frames = args.takeOption("--frames"); !frames.empty())
    study.frames = static_cast<int>(wholeNumberFlag("--frames", frames, 0, 10000, "--frames 50"));
  ThermalReplanSettings replan;
  if (const std::string limit = args.takeOption("--interpass-max"); !limit.empty())
    replan.interpassMax = finiteNumberFlag("--interpass-max", limit, "--interpass-max 250");
  const std::string remedy = args.takeOption("--remedy"), maxDwell = args.takeOption("--max-dwell");
  if ((!remedy.empty() || !maxDwell.empty()) && replan.interpassMax == 0.0)
    throw UsageError(std::string(remedy.empty() ? "--max-dwell" : "--remedy") + " needs --interpass-max",
                     "write --interpass-max 250 --remedy heat");
  if (!remedy.empty()) takeRemedies(remedy, replan);
  if (!maxDwell.empty()) {
    if (!replan.dwell) throw UsageError("--max-dwell needs the dwell remedy", "write --remedy dwell");
    replan.maxDwell = positiveValue("--max-dwell", maxDwell, "s");
  }
  // A part file is planned first, with the flags of 'plan'; a plan folder or a project is read.
  const PluginRegistry& registry = builtinRegistry();
  std::optional<PartPlanFlags> partFlags;
  if (isPartInput(args.rest)) {
    partFlags.emplace(registry);
    partFlags->take(args);
    args.rest = takeParamFlags(args.rest, partFlags->targets());
  }
  const auto positional = args.finish("thermal", 1, 1);
  if (outDir.empty()) throw UsageError("'thermal' needs an output folder", "write -o DIR");
  const fs::path input = positional[0];
  if (!fs::exists(input))
    throw InputError("'" + input.string() + "' does not exist",
                     "give a part file, the -o folder of 'spira-cli plan' or a planned .spira project");
  ensureWritableDirectory(outDir);

  NullProgress progress;
  ThermalSource source;
  bool planFeasible = true;
  if (partFlags) {
    if (!substrateZ.empty())
      partFlags->placement.substrateZ = finiteNumberFlag("--substrate-z", substrateZ, "--substrate-z 0");
    PlannedPart part = planPartFile(registry, input.string(), *partFlags, nullptr, false, progress);
    const PlannedPath planned = plannedPathOf(part.plan.results);
    source.trajectory = *planned.trajectory;
    const ProcessSettings process = readPlanSections(partFlags->planFlags.values).process;
    source.beadWidth = process.beadWidth;
    source.limits = process.limits;
    source.report = std::move(part.plan.report);
    planFeasible = part.plan.feasible;
    std::cout << "planned " << input.filename().string() << ": " << source.trajectory.size() << " points, "
              << (planFeasible ? "feasible" : "INFEASIBLE (see report.json)") << "\n";
  } else {
    source = readSource(input);
  }
  mesh.thickness = beadWidth.empty() ? source.beadWidth.value_or(ProcessSettings{}.beadWidth)
                                     : positiveValue("--bead-width", beadWidth, "mm");
  mesh.substrateZ = substrateZ.empty() ? substratePlaneOf(source.trajectory)
                                       : finiteNumberFlag("--substrate-z", substrateZ, "--substrate-z 0");
  settings.sourceRadius = radius.empty() ? 0.5 * mesh.thickness
                                         : finiteNumberFlag("--source-radius", radius, "--source-radius 2.6");
  backend.start(settings);

  // Everything is computed before the first file is written.
  const auto start = std::chrono::steady_clock::now();
  std::optional<ThermalReplanOutcome> outcome;
  std::optional<DepositCheckReport> thinnedCheck;
  ThermalStudy thermal;
  if (replan.interpassMax > 0.0) {
    replan.limits = source.limits;
    replan.hMin = source.report.is_object() ? source.report.value("h_min", 0.0) : 0.0;
    if (!(settings.powerPerWireFeed > 0.0))
      settings.powerPerWireFeed = powerPerWireFeedOf(source.trajectory, settings.power);
    outcome = replanForInterpass(source.trajectory, study, replan, progress);
    thermal = std::move(outcome->study);
    if (outcome->revolutionsAdded > 0) thinnedCheck = checkThinned(*outcome, source.report, mesh);
  } else {
    thermal = runThermalStudy(source.trajectory, study, progress);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json report = thermalJson(thermal, study);
  if (outcome) {
    report["replan"] = replanJson(*outcome, replan, thermal);
    report["timings_s"]["replan"] = seconds;
  }
  if (!backend.writes()) return kExitOk;  // under mpirun, rank 0 writes
  // A planned part or a re-planned path is written with its thermal history, as one plan set.
  const bool withPlan = partFlags || outcome;
  std::vector<OutputFile> files;
  if (withPlan) {
    files.push_back({"trajectory.csv", trajectoryCsv(outcome ? outcome->trajectory : source.trajectory)});
    nlohmann::json planReport =
        outcome ? replannedReport(source.report, *outcome, replan, thermal) : source.report;
    if (thinnedCheck) {
      planReport["deposit_check"] = reportToJson(depositCheckRecord(*thinnedCheck));
      planReport["feasible"] = planReport.value("feasible", true) && thinnedCheck->feasible;
      planFeasible = planFeasible && thinnedCheck->feasible;
    }
    files.push_back({"report.json", planReport.dump(2) + "\n"});
  }
  files.push_back({"thermal.json", report.dump(2) + "\n", withPlan});
  files.push_back({"thermal_points.csv", thermalPointsCsv(thermal), withPlan});
  files.push_back({"probes.csv", thermalProbesCsv(thermal.result), withPlan});
  for (OutputFile& f : thermalTimeSeries(thermal, "thermal")) {
    f.thermal = withPlan;
    files.push_back(std::move(f));
  }
  replaceOutputSet(outDir, withPlan ? OutputKind::Plan : OutputKind::Thermal, files);

  printStudy(thermal, settings, report);
  if (outcome) printReplan(*outcome, replan, seconds);
  if (thinnedCheck)
    std::cout << "deposit check of the thinned path: "
              << (thinnedCheck->feasible ? "feasible" : "INFEASIBLE: " + thinnedCheck->summary()) << "\n";
  if (timing)
    for (const auto& [stage, t] : report["timings_s"].items())
      std::cout << "timing " << stage << ": " << t.get<double>() << " s\n";
  std::cout << "wrote " << (withPlan ? outDir + "/trajectory.csv, report.json, " : outDir + "/")
            << "thermal.json, thermal_points.csv, probes.csv and thermal.pvd\n";
  if (outcome && !outcome->limitMet) {
    std::cerr << "error: the interpass limit cannot be met: " << outcome->why << "\n"
              << "hint: raise --interpass-max (the best reached is "
              << significantText(report["max_interpass_C"].get<double>(), 4)
              << " C), add remedies (--remedy deposit,heat,dwell), allow longer dwells, or lower the power\n";
    return kExitInfeasible;
  }
  return planFeasible ? kExitOk : kExitInfeasible;
}

}  // namespace spira::cli
