#include "spira/planning/strategy_compare.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <optional>

#include <nlohmann/json.hpp>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/planar_baseline.h"
#include "spira/plugin/strategy_name.h"

namespace spira {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void depositStats(StrategyOutcome& s, const Comparison& c)
{
  s.depositMin = s.heights.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  s.depositMax = s.heights.empty() ? 0.0 : -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  s.outside = 0;
  for (double h : s.heights) {
    s.depositMin = std::min(s.depositMin, h);
    s.depositMax = std::max(s.depositMax, h);
    sum += h;
    s.outside += h < c.hMin - c.tolerance || h > c.hMax + c.tolerance;
  }
  s.depositMean = s.heights.empty() ? 0.0 : sum / static_cast<double>(s.heights.size());
}

StrategyOutcome planWith(const PluginRegistry& registry, const PlanRequest& request, const std::string& id,
                         const Comparison& c, Progress& progress)
{
  StrategyOutcome s;
  s.strategy = strategyName(id);
  s.kind = "ctpp";
  PlanRequest r = request;
  r.decomposerId = id;
  const auto start = Clock::now();
  try {
    const PlanOutput plan = planPart(registry, r, progress);
    s.runtime = secondsSince(start);
    s.ran = true;
    s.feasible = plan.feasible();
    s.generatrixLengthMin = plan.spiral.report.generatrixLengthMin;
    s.generatrixLengthMax = plan.spiral.report.generatrixLengthMax;
    s.revolutions = plan.spiral.report.nRevolutions;
    s.paths = plan.paths.size();
    s.arcStarts = plan.layers ? plan.layers->arcStarts : int(plan.paths.size());
    if (plan.layers) {
      s.revolutions = plan.layers->output == "layers" ? plan.layers->layers : s.revolutions;
      s.maxKinkDeg = plan.layers->maxKinkDeg;
    }
    for (const TrajectoryPoint& p : plan.spiral.trajectory.points) {
      s.points.push_back(p.position);
      s.heights.push_back(p.height);
    }
    depositStats(s, c);
  } catch (const Error& e) {
    s.runtime = secondsSince(start);
    s.failure = e.fullMessage();
  }
  return s;
}

StrategyOutcome planar(const PlanRequest& request, const Comparison& c, Progress& progress)
{
  StrategyOutcome s;
  s.strategy = "planar_2.5d";
  s.kind = "planar";
  const auto start = Clock::now();
  try {
    // A thin-walled solid is sliced on the mid-surface its CTPP plans run on.
    std::optional<SolidSurface> solid;
    if (request.midSurfaceOfSolid && isClosedSolid(request.report)) {
      const double bead = readPlanSections(request.params).process.beadWidth;
      solid = plannableMidSurface(request.mesh, bead);
    }
    const TriangleMesh& mesh = solid ? *solid->wall.midSurface : request.mesh;
    const MeshReport& report = solid ? solid->report : request.report;
    const PartTopology topology =
        findPartTopology(report, mesh, request.substrateZ, request.lowerLoopOverride, /*allowBranches=*/true);
    PlanarBaselineSettings settings;
    settings.h = c.h;
    settings.hMin = c.hMin;
    settings.hMax = c.hMax;
    settings.tolerance = c.tolerance;
    const PlanarBaseline b = planarBaseline(mesh, report, topology.lowerIndex, settings, progress);
    s.runtime = secondsSince(start);
    s.ran = true;
    s.revolutions = b.layers;
    s.paths = static_cast<size_t>(b.layers);
    s.arcStarts = b.layers;
    for (const PlanarPoint& p : b.points) {
      s.points.push_back(p.position);
      s.heights.push_back(p.height);
    }
    depositStats(s, c);
    s.feasible = s.outside == 0 && !s.points.empty();
  } catch (const Error& e) {
    s.runtime = secondsSince(start);
    s.failure = e.fullMessage();
  }
  return s;
}

nlohmann::json orNull(bool has, double v)
{
  return has ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace

Comparison compareStrategies(const PluginRegistry& registry, const PlanRequest& request, Progress& progress)
{
  Comparison c;
  const SpiralSettings window = readPlanSections(request.params).spiral;
  c.h = window.h;
  c.hMin = window.hMin;
  c.hMax = window.hMax;
  c.tolerance = window.heightTolerance * window.h;
  const std::vector<const Plugin*> decomposers = registry.ofKind(PluginKind::Decomposer);
  const double steps = static_cast<double>(decomposers.size() + 1);
  for (size_t k = 0; k < decomposers.size(); ++k) {
    SubProgress p(progress, k / steps, (k + 1) / steps, decomposers[k]->id());
    c.strategies.push_back(planWith(registry, request, decomposers[k]->id(), c, p));
  }
  SubProgress p(progress, decomposers.size() / steps, 1.0, "planar 2.5D slicing");
  c.strategies.push_back(planar(request, c, p));
  return c;
}

nlohmann::json comparisonJson(const Comparison& comparison)
{
  nlohmann::json list = nlohmann::json::array();
  for (const StrategyOutcome& s : comparison.strategies) {
    const bool ctpp = s.ran && s.kind == "ctpp";
    list.push_back({{"strategy", s.strategy},
                    {"kind", s.kind},
                    {"ran", s.ran},
                    {"feasible", s.feasible},
                    {"failure", s.ran ? nlohmann::json(nullptr) : nlohmann::json(s.failure)},
                    {"generatrix_length_min", orNull(ctpp, s.generatrixLengthMin)},
                    {"generatrix_length_max", orNull(ctpp, s.generatrixLengthMax)},
                    {"generatrix_length_spread", orNull(ctpp, s.generatrixLengthMax - s.generatrixLengthMin)},
                    {"deposit_min", orNull(s.ran, s.depositMin)},
                    {"deposit_max", orNull(s.ran, s.depositMax)},
                    {"deposit_mean", orNull(s.ran, s.depositMean)},
                    {"n_points", s.points.size()},
                    {"points_outside_window", s.outside},
                    {"revolutions", s.revolutions},
                    {"n_paths", s.paths},
                    {"n_arc_starts", s.arcStarts},
                    {"max_kink_deg", orNull(s.ran && s.maxKinkDeg >= 0.0, s.maxKinkDeg)},
                    {"runtime_s", s.runtime}});
  }
  return {{"h", comparison.h},
          {"h_min", comparison.hMin},
          {"h_max", comparison.hMax},
          {"height_tolerance_mm", comparison.tolerance},
          {"strategies", list}};
}

std::string comparisonCsv(const Comparison& comparison)
{
  std::string out = "strategy,x,y,z,height\n";
  for (const StrategyOutcome& s : comparison.strategies)
    for (size_t i = 0; i < s.points.size(); ++i) {
      out += s.strategy;
      for (int k = 0; k < 3; ++k) {
        out += ',';
        appendNumber(out, s.points[i][k]);
      }
      out += ',';
      appendNumber(out, s.heights[i]);
      out += '\n';
    }
  return out;
}

void writeComparisonFiles(const Comparison& comparison, const std::filesystem::path& dir)
{
  const std::string csv = comparisonCsv(comparison);
  const std::string json = comparisonJson(comparison).dump(2) + "\n";
  writeFileAtomically(dir / "compare.csv", csv);
  writeFileAtomically(dir / "compare.json", json);
}

}  // namespace spira
