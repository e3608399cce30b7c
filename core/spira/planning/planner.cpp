#include "spira/planning/planner.h"

#include <chrono>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/field/harmonic_field.h"
#include "spira/field/heat_distance.h"
#include "spira/path/spiral_builder.h"
#include "spira/planning/plan_schemas.h"

namespace spira {
namespace {

class StageClock {
 public:
  explicit StageClock(StageTimings& timings) : timings_(timings) {}
  void lap(const std::string& stage)
  {
    const auto now = std::chrono::steady_clock::now();
    timings_.emplace_back(stage, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  StageTimings& timings_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

ParamSet paramsFor(const PlanRequest& r, const std::string& section)
{
  auto it = r.params.find(section);
  return it == r.params.end() ? ParamSet() : it->second;
}

}  // namespace

PlanOutput planPart(const PluginRegistry& registry, const PlanRequest& request, Progress& progress)
{
  // Settings first: a contradictory window is reported before any computation.
  SpiralSettings spiralSettings = spiralSettingsFrom(paramsFor(request, "spiral"));
  const ProcessSettings processSettings = processSettingsFrom(paramsFor(request, "process"));
  if (spiralSettings.minRevolutionLength <= 0.0)
    spiralSettings.minRevolutionLength = kPi * processSettings.beadWidth;
  const DecomposerPlugin& decomposer = registry.decomposer(request.decomposerId);
  const ParamSet decomposerParams =
      paramsFor(request, request.decomposerId).withDefaults(decomposer.schema());
  decomposer.schema().validate(decomposerParams);

  PlanOutput out;
  StageClock clock(out.timings);
  out.topology =
      findPartTopology(request.report, request.mesh, request.substrateZ, request.lowerLoopOverride);
  const bool open = out.topology.partClass == PartClass::Open;
  clock.lap("topology");

  if (open) {
    SubProgress p(progress, 0.0, 0.3, "harmonic field");
    out.fieldKind = "harmonic";
    out.field = harmonicField(request.mesh, out.topology.lower.vertices, out.topology.upper->vertices, p);
    clock.lap("field");
  } else {
    SubProgress p(progress, 0.0, 0.3, "geodesic distance from the base");
    out.fieldKind = "geodesic_distance";
    out.field = heatGeodesicDistance(request.mesh, out.topology.lower.vertices, HeatDistanceOptions{}, p);
    clock.lap("field");
    const ClosureFinderPlugin& finder = registry.closureFinder(request.closureFinderId);
    SubProgress cp(progress, 0.3, 0.35, "closure point");
    out.closure = finder.find({request.mesh, out.topology.lower.vertices, &out.field},
                              paramsFor(request, request.closureFinderId), cp);
    out.hasClosure = true;
    out.warnings.insert(out.warnings.end(), out.closure.warnings.begin(), out.closure.warnings.end());
    clock.lap("closure");
  }
  progress.checkCancel();

  DecomposeInput input{request.mesh,
                       out.topology.partClass,
                       out.topology.lower,
                       out.topology.upper,
                       out.hasClosure ? std::optional<Vec3>(out.closure.point) : std::nullopt,
                       &out.field};
  std::string why;
  if (!decomposer.accepts(input, &why))
    throw InputError(decomposer.id() + " cannot plan this part: " + why,
                     "choose another strategy with --strategy");
  SubProgress dp(progress, 0.35, 0.8, "generatrices");
  DecomposeResult decomposition = decomposer.decompose(input, decomposerParams, dp);
  out.generatrices = std::move(decomposition.generatrices);
  out.warnings.insert(out.warnings.end(), decomposition.warnings.begin(), decomposition.warnings.end());
  clock.lap("decomposition");

  SubProgress sp(progress, 0.8, 0.95, "spiral");
  out.spiral = buildSpiral(out.generatrices, spiralSettings, sp);
  clock.lap("spiral");
  out.process = applyProcess(out.spiral.trajectory, processSettings);
  if (!out.process.violations.empty()) {
    const ProcessViolation& first = out.process.violations.front();
    out.warnings.push_back(
        std::to_string(out.process.violations.size()) +
        " point(s) need speeds outside the process limits and were clamped to them (first: point " +
        std::to_string(first.point) + ", " + processViolationName(first.kind) + ")");
  }
  clock.lap("process");
  progress.report(1.0, "done");
  return out;
}

}  // namespace spira
