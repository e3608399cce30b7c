#include "thermal_outputs.h"

#include <algorithm>
#include <iostream>

#include "spira/base/number_text.h"
#include "spira/path/dwell.h"
#include "spira/pipeline/thermal_stage.h"

namespace spira::cli {
std::string thermalPointsCsv(const ThermalStudy& study)
{
  const ThermalResult& r = study.result;
  std::string out = "index,peak_C,interpass_C,time_above_melt_s,bond,risk,below_at_arrival_C,pool_mm\n";
  for (size_t i = 0; i < r.peak.size(); ++i) {
    appendNumber(out, static_cast<long long>(i));
    for (double v : {r.peak[i], r.interpass[i], r.timeAboveMelt[i], study.bond[i]}) {
      out += ',';
      appendNumber(out, v);
    }
    out += study.risk[i] ? ",1" : ",0";
    for (double v : {r.belowAtArrival[i], study.poolLength[i]}) {
      out += ',';
      appendNumber(out, v);
    }
    out += '\n';
  }
  return out;
}

std::string thermalProbesCsv(const ThermalResult& r)
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

nlohmann::json thermalJson(const ThermalStudy& study, const ThermalStudySettings& settings)
{
  const ThermalResult& r = study.result;
  // The extremes as the plan's thermal stage reports them.
  const ThermalStageReport summary = thermalStageReportOf(study, settings, 0.0);
  const ThermalSettings& s = settings.solver;
  const ThermalMeshSettings& m = settings.mesh;
  size_t aboveMeltAtInterpass = 0;
  for (double t : r.interpass) aboveMeltAtInterpass += t >= s.material.meltingTemperature;
  return {
      {"material",
       {{"name", s.material.name},
        {"density_kg_m3", s.material.density},
        {"conductivity_W_mK", s.material.conductivity},
        {"specific_heat_J_kgK", s.material.specificHeat},
        {"melting_C", s.material.meltingTemperature},
        {"emissivity", s.material.emissivity},
        {"source", s.material.source}}},
      {"power_W", s.power},
      {"power_per_wire_feed_J_mm", s.powerPerWireFeed},
      {"power_table_rows", s.powerTable.size()},
      {"source_radius_mm", s.sourceRadius},
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
      {"max_peak_C", summary.maxPeak},
      {"max_interpass_C", summary.maxInterpass},
      {"n_points_molten_below_at_interpass", aboveMeltAtInterpass},
      {"max_pool_length_mm", summary.maxPoolLength},
      {"max_bond", summary.maxBond},
      {"bond_threshold", settings.bondThreshold},
      {"n_risk_points", study.riskPoints},
      {"n_nodes", r.nodes},
      {"n_elements", r.elements},
      {"n_steps", r.steps},
      {"simulated_time_s", r.simulatedTime},
      {"mean_unknowns_per_step", r.meanWindow},
      {"mean_solver_iterations", r.solverIterations},
      {"timings_s", {{"mesh", study.meshSeconds}, {"simulation", r.seconds}, {"solver", r.solverSeconds}}}};
}

nlohmann::json replanJson(const ThermalReplanOutcome& o, const ThermalReplanSettings& replan,
                          const ThermalStudy& final)
{
  nlohmann::json j = {
      {"interpass_max_C", replan.interpassMax},
      {"remedy", remediesText(replan)},
      {"applied", o.applied},
      {"limit_met", o.limitMet},
      {"revolutions_added", o.revolutionsAdded},
      {"thinnest_deposit_ratio", o.thinnestRatio},
      {"revolutions_slowed", o.revolutionsChanged},
      {"slowest_speed_factor", o.slowestFactor},
      {"dwells", o.dwells},
      {"dwell_time_s", o.dwellTime},
      {"arc_starts_added", o.dwells},
      {"build_time_added_s", o.buildTimeAdded},
      {"re_simulations", o.rounds},
      {"planned_max_interpass_C", o.plannedWorst},
      {"final_max_interpass_C", thermalStageReportOf(final, ThermalStudySettings{}, 0.0).maxInterpass}};
  if (!o.why.empty()) j["why_not_met"] = o.why;
  return j;
}

void printReplan(const ThermalReplanOutcome& o, const ThermalReplanSettings& replan, double seconds)
{
  std::cout << "re-planned for an interpass limit of " << significantText(replan.interpassMax, 4) << " C ("
            << remediesText(replan) << "):";
  if (o.applied.empty()) std::cout << " no change;";
  for (const std::string& remedy : o.applied) {
    if (remedy == "deposit")
      std::cout << " " << o.revolutionsAdded << " revolution(s) added (deposit down to "
                << significantText(100.0 * o.thinnestRatio, 3) << " %);";
    else if (remedy == "heat")
      std::cout << " " << o.revolutionsChanged << " revolution(s) slowed (down to "
                << significantText(100.0 * o.slowestFactor, 3) << " % speed);";
    else if (remedy == "dwell")
      std::cout << " " << o.dwells << " dwell(s), " << significantText(o.dwellTime, 4) << " s in all, "
                << o.dwells << " arc start(s) added;";
  }
  std::cout << " build time +" << significantText(o.buildTimeAdded, 4) << " s, " << o.rounds
            << " re-simulation(s) in " << significantText(seconds, 3) << " s\n";
}

nlohmann::json replannedReport(nlohmann::json report, const ThermalReplanOutcome& o,
                               const ThermalReplanSettings& replan, const ThermalStudy& final)
{
  double tsMin = 1e300, tsMax = 0.0, wfsMin = 1e300, wfsMax = 0.0;
  for (const TrajectoryPoint& p : o.trajectory.points) {
    tsMin = std::min(tsMin, p.travelSpeed);
    tsMax = std::max(tsMax, p.travelSpeed);
    wfsMin = std::min(wfsMin, p.wireFeed);
    wfsMax = std::max(wfsMax, p.wireFeed);
  }
  if (report.contains("n_points")) report["n_points"] = o.trajectory.size();
  if (report.contains("n_revolutions"))
    report["n_revolutions"] = report["n_revolutions"].get<long long>() + o.revolutionsAdded;
  if (report.contains("path_length")) report["path_length"] = o.trajectory.length();
  if (report.contains("build_time_s"))
    report["build_time_s"] = report["build_time_s"].get<double>() + o.buildTimeAdded;
  if (const DwellTotals dwells = dwellTotals(o.trajectory); dwells.count > 0) {
    report["n_dwells"] = dwells.count;
    report["dwell_time_s"] = dwells.seconds;
  }
  if (report.contains("process") && report["process"].is_object()) {
    nlohmann::json& p = report["process"];
    p["ts_min_mm_s"] = tsMin;
    p["ts_max_mm_s"] = tsMax;
    p["wfs_min_m_min"] = wfsMin * 60.0 / 1000.0;
    p["wfs_max_m_min"] = wfsMax * 60.0 / 1000.0;
  }
  report["thermal_replan"] = replanJson(o, replan, final);
  return report;
}

}  // namespace spira::cli
