#include "spira/planning/plan_files.h"

#include <nlohmann/json.hpp>

#include "spira/base/atomic_file.h"
#include "spira/base/number_text.h"
#include "spira/base/units.h"

namespace spira {
namespace {

void putVec(std::string& out, const Vec3& v)
{
  for (int k = 0; k < 3; ++k) {
    appendNumber(out, v[k]);
    out += ',';
  }
}

constexpr double kMmPerSecondToMetresPerMinute = 60.0 / 1000.0;

}  // namespace

std::string trajectoryCsv(const Trajectory& trajectory)
{
  std::string out = "index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc\n";
  out.reserve(out.size() + trajectory.size() * 220);
  for (size_t i = 0; i < trajectory.size(); ++i) {
    const TrajectoryPoint& p = trajectory.points[i];
    appendNumber(out, static_cast<long long>(i));
    out += ',';
    putVec(out, p.position);
    putVec(out, p.normal);
    putVec(out, p.tangent);
    putVec(out, p.build);
    appendNumber(out, static_cast<long long>(p.revolution));
    out += ',';
    appendNumber(out, static_cast<long long>(p.generatrix));
    out += ',';
    appendNumber(out, p.height);
    out += ',';
    appendNumber(out, p.travelSpeed);
    out += ',';
    appendNumber(out, p.wireFeed * kMmPerSecondToMetresPerMinute);
    out += p.arcOn ? ",1\n" : ",0\n";
  }
  return out;
}

nlohmann::json planReportJson(const PlanOutput& plan, const std::string& strategy)
{
  const SpiralReport& s = plan.spiral.report;
  nlohmann::json j;
  j["part_type"] = plan.topology.partClass == PartClass::Open ? "open" : "closed";
  j["strategy"] = strategy;
  j["field"] = plan.fieldKind;
  j["n_generatrices"] = plan.generatrices.lines.size();
  j["generatrix_length_min"] = s.generatrixLengthMin;
  j["generatrix_length_max"] = s.generatrixLengthMax;
  j["n_startup_revolutions"] = s.nStartupRevolutions;
  j["n_layers"] = s.nLayers;
  j["n_end_revolutions"] = s.nEndRevolutions;
  j["n_revolutions"] = s.nRevolutions;
  j["n_points"] = s.nPoints;
  j["step_min"] = s.stepMin;
  j["step_max"] = s.stepMax;
  j["height_min"] = s.heightMin;
  j["height_max"] = s.heightMax;
  j["height_mean"] = s.heightMean;
  j["feasible"] = plan.feasible();
  j["window_feasible"] = s.feasible;
  j["length_criterion"] = {
      {"length_min", s.lengthCriterion.lengthMin}, {"length_max", s.lengthCriterion.lengthMax},
      {"n_layers", s.lengthCriterion.nLayers},     {"step_spread", s.lengthCriterion.stepSpread},
      {"window", s.lengthCriterion.window},        {"ok", s.lengthCriterion.ok}};
  j["violations"] = s.violations.size();
  j["modulated_violations"] = s.modulatedViolations;
  j["closure_gap"] = s.closureGap;
  nlohmann::json points = nlohmann::json::array();
  for (const auto& v : s.violations) {
    if (points.size() >= 1000) break;
    points.push_back({{"point", v.point},
                      {"revolution", v.revolution},
                      {"generatrix", v.generatrix},
                      {"height", v.height},
                      {"phase", spiralPhaseName(v.phase)},
                      {"above", v.aboveWindow}});
  }
  j["violation_points"] = points;
  j["closure_point"] =
      plan.hasClosure
          ? nlohmann::json::array({plan.closure.point.x(), plan.closure.point.y(), plan.closure.point.z()})
          : nlohmann::json(nullptr);
  if (plan.hasClosure) j["closure_distance"] = plan.closure.distance;
  j["path_length"] = s.pathLength;
  j["max_jump"] = s.maxJump;
  j["seam_rise_max"] = s.seamRiseMax;
  j["build_time_s"] = plan.process.buildTime;
  j["process"] = {{"within_limits", plan.process.withinLimits},
                  {"ts_min_mm_s", plan.process.travelSpeedMin},
                  {"ts_max_mm_s", plan.process.travelSpeedMax},
                  {"wfs_min_m_min", plan.process.wireFeedMin * kMmPerSecondToMetresPerMinute},
                  {"wfs_max_m_min", plan.process.wireFeedMax * kMmPerSecondToMetresPerMinute},
                  {"wire_length_mm", plan.process.wireLength},
                  {"deposit_volume_mm3", plan.process.depositVolume},
                  {"limit_violations", plan.process.violations.size()}};
  nlohmann::json timings = nlohmann::json::object();
  double total = 0.0;
  for (const auto& [stage, seconds] : plan.timings) {
    timings[stage] = seconds;
    total += seconds;
  }
  timings["total"] = total;
  j["timings_s"] = timings;
  j["warnings"] = plan.warnings;
  return j;
}

void writePlanFiles(const PlanOutput& plan, const std::string& strategy, const std::filesystem::path& dir)
{
  const std::string csv = trajectoryCsv(plan.spiral.trajectory);
  const std::string report = planReportJson(plan, strategy).dump(2) + "\n";
  writeFileAtomically(dir / "trajectory.csv", csv);
  writeFileAtomically(dir / "report.json", report);
}

}  // namespace spira
