#include "spira/planning/plan_files.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "spira/base/number_text.h"
#include "spira/base/units.h"
#include "spira/plugin/strategy_name.h"

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

const char* partTypeName(PartClass c)
{
  return c == PartClass::Open ? "open" : "closed";
}

nlohmann::json point(const Vec3& p)
{
  return nlohmann::json::array({p.x(), p.y(), p.z()});
}

nlohmann::json pathJson(const PathSummary& p)
{
  const SpiralReport& s = p.spiral;
  return {{"path", p.path},
          {"parent", p.parent},
          {"depth", p.depth},
          {"role", p.trunk ? "trunk" : "branch"},
          {"part_type", partTypeName(p.partClass)},
          {"base_level", p.baseLevel},
          {"area_mm2", p.area},
          {"first_point", p.firstPoint},
          {"n_points", p.pointCount},
          {"n_generatrices", p.generatrices},
          {"generatrix_length_min", s.generatrixLengthMin},
          {"generatrix_length_max", s.generatrixLengthMax},
          {"n_revolutions", s.nRevolutions},
          {"height_min", s.heightMin},
          {"height_max", s.heightMax},
          {"height_mean", s.heightMean},
          {"feasible", p.feasible()},
          {"deposit_flags", p.depositFlags},
          {"violations", s.violations.size()},
          {"path_length", s.pathLength},
          {"max_jump", s.maxJump},
          {"build_time_s", p.process.buildTime},
          {"closure_point", p.hasClosure ? point(p.closure.point) : nlohmann::json(nullptr)}};
}

nlohmann::json branchingJson(const BranchingSummary& b)
{
  nlohmann::json saddles = nlohmann::json::array();
  for (const BranchSaddle& s : b.saddles)
    saddles.push_back({{"below_path", s.piece},
                       {"level", s.level},
                       {"position", point(s.position)},
                       {"branches", s.branches},
                       {"trunk_top_level", s.trunkTop},
                       {"branch_base_level", s.branchBase},
                       {"gap_area_mm2", s.gapArea},
                       {"bisections", s.bisections}});
  return {{"saddles", saddles},
          {"junction_gap_mm", b.junctionGap},
          {"junction_gap_area_mm2", b.junctionGapArea},
          {"depth_limited", b.depthLimited}};
}

nlohmann::json depositCheckJson(const DepositCheckReport& d)
{
  nlohmann::json counts = nlohmann::json::object();
  for (int k = 0; k < 5; ++k) counts[depositDefectName(static_cast<DepositDefect>(k))] = d.counts[k];
  nlohmann::json points = nlohmann::json::array();
  for (const DepositFlag& f : d.flags) {
    if (points.size() >= 1000) break;
    points.push_back(
        {{"point", f.point},
         {"kind", depositDefectName(f.kind)},
         {"height", std::isfinite(f.height) ? nlohmann::json(f.height) : nlohmann::json(nullptr)},
         {"position", point(f.position)}});
  }
  nlohmann::json j = {{"feasible", d.feasible},
                      {"summary", d.summary()},
                      {"points_checked", d.pointsChecked},
                      {"height_min", d.heightMin},
                      {"height_max", d.heightMax},
                      {"height_mean", d.heightMean},
                      {"planned_difference_max", d.plannedDifferenceMax},
                      {"jump_length", d.jumpLength},
                      {"counts", counts},
                      {"flagged", d.flags.size()},
                      {"flagged_points", points}};
  if (d.coverageChecked)
    j["coverage"] = {{"surface_area_mm2", d.surfaceArea},
                     {"uncovered_area_mm2", d.uncoveredArea},
                     {"uncovered_fraction", d.uncoveredFraction()},
                     {"cover_radius_mm", d.coverRadius},
                     {"largest_gap_mm", d.largestGap},
                     {"largest_gap_at", point(d.largestGapAt)}};
  return j;
}

}  // namespace

std::string trajectoryCsv(const Trajectory& trajectory)
{
  std::string out = "index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc,path\n";
  out.reserve(out.size() + trajectory.size() * 224);
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
    out += p.arcOn ? ",1," : ",0,";
    appendNumber(out, static_cast<long long>(p.path));
    out += '\n';
  }
  return out;
}

nlohmann::json planReportJson(const PlanOutput& plan, const std::string& strategy)
{
  const SpiralReport& s = plan.spiral.report;
  nlohmann::json j;
  j["part_type"] = plan.branching ? "multi_branch" : partTypeName(plan.topology.partClass);
  j["strategy"] = strategyName(strategy);
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
  j["ramp_height_min"] = s.rampHeightMin;
  j["ramp_height_max"] = s.rampHeightMax;
  j["h"] = s.h;
  j["h_min"] = s.hMin;
  j["h_max"] = s.hMax;
  j["height_tolerance_mm"] = s.heightTolerance;
  j["collapsed_revolutions"] = s.collapsedRevolutions;
  j["feasible"] = plan.feasible();
  j["window_feasible"] = s.feasible;
  j["deposit_check"] = depositCheckJson(plan.deposits);
  if (plan.solid) j["solid"] = plan.solid->toJson();
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
  j["n_paths"] = plan.paths.empty() ? size_t{1} : plan.paths.size();
  nlohmann::json paths = nlohmann::json::array();
  for (const PathSummary& p : plan.paths) paths.push_back(pathJson(p));
  j["paths"] = paths;
  if (plan.branching) j["branching"] = branchingJson(*plan.branching);
  return j;
}

nlohmann::json adviceJson(const PlanAdvice& advice)
{
  return {{"found", advice.found},
          {"change", advice.change},
          {"flags", advice.flags},
          {"tried", advice.tried},
          {"cause", advice.cause}};
}

}  // namespace spira
