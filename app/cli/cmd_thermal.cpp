#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/base/output_set.h"
#include "spira/base/progress.h"
#include "spira/document/document.h"
#include "spira/pipeline/planned_path.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/trajectory_csv_reader.h"
#include "spira/thermal/thermal_solver.h"
#include "thermal_backend.h"

namespace fs = std::filesystem;

namespace spira::cli {
namespace {

constexpr double kDefaultEfficiency = 0.8;  // GMAW/CMT arc efficiency, DuPont & Marder 1995: 0.8-0.85

// What the thermal model runs on: a planned path with its process channels.
struct ThermalSource {
  Trajectory trajectory;
  std::optional<double> beadWidth;  // mm, from a project's process settings
};

ThermalSource readSource(const fs::path& input)
{
  ThermalSource s;
  if (fs::is_directory(input)) {
    verifyOutputSet(input);
    s.trajectory = readTrajectoryCsv(input / "trajectory.csv");
    return s;
  }
  Document doc;
  doc.open(input);
  const PlannedPath planned = plannedPathOf(doc.results());
  if (!planned.trajectory || planned.trajectory->empty())
    throw InputError("the project '" + input.string() + "' holds no planned trajectory",
                     "plan it first (Plan in Spira, or spira-cli plan PROJECT --save), then simulate it");
  s.trajectory = *planned.trajectory;
  s.beadWidth = readPlanSections(doc.settings()->params).process.beadWidth;
  return s;
}

// The plane the first revolution rests on: each of its points lies its deposit height above it,
// along the point's build direction.
double substratePlaneOf(const Trajectory& t)
{
  double z = std::numeric_limits<double>::infinity();
  for (const TrajectoryPoint& p : t.points) {
    if (p.revolution != t.points.front().revolution || p.path != t.points.front().path) break;
    z = std::min(z, (p.position - p.height * p.build).z());
  }
  return z;
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

double arcPowerFrom(Args& args)
{
  const std::string power = args.takeOption("--power"), voltage = args.takeOption("--voltage"),
                    current = args.takeOption("--current"), efficiency = args.takeOption("--efficiency");
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

std::string pointsCsv(const ThermalResult& r)
{
  std::string out = "index,peak_C,interpass_C,below_at_arrival_C,time_above_melt_s\n";
  for (size_t i = 0; i < r.peak.size(); ++i) {
    appendNumber(out, static_cast<long long>(i));
    for (double v : {r.peak[i], r.interpass[i], r.belowAtArrival[i], r.timeAboveMelt[i]}) {
      out += ',';
      appendNumber(out, v);
    }
    out += '\n';
  }
  return out;
}

std::string probesCsv(const ThermalResult& r)
{
  std::string out = "t";
  for (int node : r.probeNodes) out += ",node_" + std::to_string(node) + "_C";
  out += '\n';
  for (size_t k = 0; k < r.probeTimes.size(); ++k) {
    appendNumber(out, r.probeTimes[k]);
    for (const auto& history : r.probeTemperatures) {
      out += ',';
      appendNumber(out, history[k]);
    }
    out += '\n';
  }
  return out;
}

double maxOf(const std::vector<double>& v)
{
  return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
}

nlohmann::json thermalJson(const ThermalResult& r, const ThermalSettings& s, const ThermalMeshSettings& m,
                           double meshSeconds)
{
  size_t aboveMeltAtInterpass = 0;
  for (double t : r.interpass) aboveMeltAtInterpass += t >= s.material.meltingTemperature;
  return {{"material",
           {{"name", s.material.name},
            {"density_kg_m3", s.material.density},
            {"conductivity_W_mK", s.material.conductivity},
            {"specific_heat_J_kgK", s.material.specificHeat},
            {"melting_C", s.material.meltingTemperature},
            {"source", s.material.source}}},
          {"power_W", s.power},
          {"scheme", s.scheme == ThermalScheme::CrankNicolson ? "crank_nicolson" : "implicit_euler"},
          {"time_step_s", s.timeStep > 0.0 ? nlohmann::json(s.timeStep) : nlohmann::json("auto")},
          {"sub_segments", m.subSegments},
          {"divisions", m.divisions},
          {"substrate_z_mm", m.substrateZ},
          {"shell_thickness_mm", m.thickness},
          {"h_air_W_m2K", s.films.air},
          {"h_substrate_W_m2K", s.films.substrate},
          {"energy_in_J", r.energy.in},
          {"energy_stored_J", r.energy.stored},
          {"energy_lost_J", r.energy.lost},
          {"energy_imbalance_J", r.energy.imbalance()},
          {"max_peak_C", maxOf(r.peak)},
          {"max_interpass_C", maxOf(r.interpass)},
          {"n_points_molten_below_at_interpass", aboveMeltAtInterpass},
          {"n_nodes", r.nodes},
          {"n_elements", r.elements},
          {"n_steps", r.steps},
          {"simulated_time_s", r.simulatedTime},
          {"mean_unknowns_per_step", r.meanWindow},
          {"mean_solver_iterations", r.solverIterations},
          {"timings_s", {{"mesh", meshSeconds}, {"simulation", r.seconds}, {"solver", r.solverSeconds}}}};
}

constexpr const char* kHelp =
    "usage: spira-cli thermal PLAN_DIR|PROJECT.spira -o DIR [--material NAME] [--power W | --voltage V\n"
    "                         --current A [--efficiency E]] [--dt auto|S] [--probe X,Y,Z]...\n"
    "                         [--sub-segments K] [--divisions F] [--bead-width MM] [--substrate-z Z]\n"
    "                         [--scheme crank-nicolson|implicit-euler] [--cooling S] [--timing]\n"
    "                         [--backend eigen|petsc]\n\n"
    "Simulates the heat of the build along the planned path (docs/thermal.md): a shell of the deposit\n"
    "as thick as the bead, born where the torch lays it, heated by the arc as a moving point source,\n"
    "cooled by the air on both faces and by the substrate. Writes DIR/thermal.json (energy in, stored\n"
    "and lost, the highest peak and interpass temperatures, nodes, steps, times), DIR/thermal_points.csv\n"
    "(per planned point: peak, interpass - the lowest the deposit below it cooled to before the torch\n"
    "came back -, the temperature below at the torch's arrival, the time above melting) and\n"
    "DIR/probes.csv (temperature against time at each --probe, the nearest node).\n\n"
    "  --material NAME   G3Si1 (default, the source's steel), 316L, Ti-6Al-4V, AlMg5\n"
    "  --power W         arc power reaching the part (default 1000 W, the source's base case), or\n"
    "  --voltage V --current A [--efficiency E]   its product (E default 0.8)\n"
    "  --dt auto|S       time step; auto (default) moves the torch one sub-segment per step\n"
    "  --sub-segments K  mesh sub-segments per planned segment (default 1); --divisions F across a layer\n"
    "  --bead-width MM   shell thickness (default: the project's bead width, else 5.2 mm)\n"
    "  --substrate-z Z   the plate's plane (default: under the first revolution, its deposit height down)\n"
    "  --cooling S       seconds simulated after the arc stops (default 0)\n"
    "  --backend NAME    linear solves in this process (eigen, default) or on PETSc (petsc), also across\n"
    "                    processes: mpirun -n N spira-cli thermal ... --backend petsc (rank 0 writes)\n"
    "Exit codes: 0 done, 2 usage, 3 bad input (unknown material, non-positive power, a time step too long\n"
    "for the torch, a plan without process channels, petsc or mpirun in a build without PETSc).\n";

}  // namespace

int cmdThermal(const std::vector<std::string>& argv)
{
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout << kHelp;
    return kExitOk;
  }
  ThermalBackend backend(args);  // first, so that under mpirun only rank 0 reports what is wrong
  const bool timing = args.takeSwitch("--timing");
  const std::string outDir = args.takeOption("-o");
  ThermalSettings settings;
  ThermalMeshSettings mesh;
  if (const std::string name = args.takeOption("--material"); !name.empty())
    settings.material = thermalMaterialPreset(name);
  settings.power = arcPowerFrom(args);
  if (const std::string dt = args.takeOption("--dt"); !dt.empty() && dt != "auto")
    settings.timeStep = positiveValue("--dt", dt, "s");
  for (std::string p = args.takeOption("--probe"); !p.empty(); p = args.takeOption("--probe"))
    settings.probePositions.push_back(probeFlag(p));
  if (const std::string k = args.takeOption("--sub-segments"); !k.empty())
    mesh.subSegments = static_cast<int>(wholeNumberFlag("--sub-segments", k, 1, 64, "--sub-segments 2"));
  if (const std::string f = args.takeOption("--divisions"); !f.empty())
    mesh.divisions = static_cast<int>(wholeNumberFlag("--divisions", f, 1, 16, "--divisions 2"));
  const std::string beadWidth = args.takeOption("--bead-width"),
                    substrateZ = args.takeOption("--substrate-z");
  if (const std::string scheme = args.takeOption("--scheme"); !scheme.empty()) {
    if (scheme == "implicit-euler")
      settings.scheme = ThermalScheme::ImplicitEuler;
    else if (scheme != "crank-nicolson")
      throw UsageError("--scheme " + scheme + " is not a time scheme",
                       "write --scheme crank-nicolson or --scheme implicit-euler");
  }
  if (const std::string cooling = args.takeOption("--cooling"); !cooling.empty())
    settings.coolingTime = finiteNumberFlag("--cooling", cooling, "--cooling 600");
  const auto positional = args.finish("thermal", 1, 1);
  if (outDir.empty()) throw UsageError("'thermal' needs an output folder", "write -o DIR");
  const fs::path input = positional[0];
  if (!fs::exists(input))
    throw InputError("'" + input.string() + "' does not exist",
                     "give the -o folder of 'spira-cli plan' or a planned .spira project");
  ensureWritableDirectory(outDir);

  const ThermalSource source = readSource(input);
  mesh.thickness = beadWidth.empty() ? source.beadWidth.value_or(ProcessSettings{}.beadWidth)
                                     : positiveValue("--bead-width", beadWidth, "mm");
  mesh.substrateZ = substrateZ.empty() ? substratePlaneOf(source.trajectory)
                                       : finiteNumberFlag("--substrate-z", substrateZ, "--substrate-z 0");
  const auto start = std::chrono::steady_clock::now();
  const ThermalMesh shell = buildThermalMesh(source.trajectory, mesh);
  const double meshSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  NullProgress progress;
  backend.start(settings);
  const ThermalResult result = simulateThermal(shell, settings, progress);
  if (!backend.writes()) return kExitOk;  // under mpirun, rank 0 writes

  // Everything is computed before the first file is written.
  const nlohmann::json report = thermalJson(result, settings, mesh, meshSeconds);
  writeFileAtomically(fs::path(outDir) / "thermal_points.csv", pointsCsv(result));
  writeFileAtomically(fs::path(outDir) / "probes.csv", probesCsv(result));
  writeFileAtomically(fs::path(outDir) / "thermal.json", report.dump(2) + "\n");
  std::cout << "thermal: " << result.nodes << " nodes, " << result.steps << " steps, "
            << significantText(result.simulatedTime, 4) << " s of build simulated in "
            << significantText(result.seconds, 3) << " s\n"
            << "peak " << significantText(report["max_peak_C"].get<double>(), 4) << " C, interpass up to "
            << significantText(report["max_interpass_C"].get<double>(), 4) << " C (" << settings.material.name
            << " melts at " << significantText(settings.material.meltingTemperature, 4) << " C)\n"
            << "energy: in " << significantText(result.energy.in, 4) << " J, stored "
            << significantText(result.energy.stored, 4) << " J, lost "
            << significantText(result.energy.lost, 4) << " J\n";
  if (timing)
    for (const auto& [stage, seconds] : report["timings_s"].items())
      std::cout << "timing " << stage << ": " << seconds.get<double>() << " s\n";
  std::cout << "wrote " << outDir << "/thermal.json, thermal_points.csv and probes.csv\n";
  return kExitOk;
}

}  // namespace spira::cli
