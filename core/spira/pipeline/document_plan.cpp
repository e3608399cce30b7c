#include "spira/pipeline/document_plan.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/document/invalidation.h"
#include "spira/mesh/mesh_report.h"
#include "spira/pipeline/document_motion.h"
#include "spira/pipeline/plan_records.h"
#include "spira/pipeline/substrate_frame.h"
#include "spira/pipeline/thermal_stage.h"
#include "spira/planning/placement_frame.h"
#include "spira/planning/plan_advice.h"
#include "spira/planning/plan_files.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/planner.h"
#include "spira/planning/settings_sections.h"

namespace spira {

namespace {

// Of the job's progress: planPart() up to kPlanShare, the optional thermal stage up to
// kThermalShare, the kinematics the rest.
constexpr double kPlanShare = 0.8;
constexpr double kThermalShare = 0.9;

std::string summaryLine(const PlanOutput& plan)
{
  const SpiralReport& s = plan.spiral.report;
  char ramps[96] = "";
  if (s.rampHeightMax > 0.0)
    std::snprintf(ramps, sizeof ramps, " (ramps %.3f to %.3f mm)", s.rampHeightMin, s.rampHeightMax);
  char text[400];
  std::snprintf(
      text, sizeof text,
      "%d revolutions%s, %zu points, path %.2f m, deposit height %.3f to %.3f mm%s, build time %.1f min",
      s.nRevolutions - s.collapsedRevolutions, plan.hasClosure ? " and the closure point" : "", s.nPoints,
      s.pathLength / 1000.0, s.heightMin, s.heightMax, ramps, plan.process.buildTime / 60.0);
  return text;
}

}  // namespace

const std::array<PlanStageSpan, kPlanStageCount>& planStageSpans()
{
  static const std::array<PlanStageSpan, kPlanStageCount> spans{{
      // planPart()'s own spans scaled into [0, 0.8] (kPlanShare), the thermal stage (skipped when
      // off), then the cell's motion.
      {"Scalar field", 0.0, 0.24},
      {"Closure point", 0.24, 0.28},
      {"Generatrices", 0.28, 0.64},
      {"Spiral", 0.64, 0.76},
      {"Process", 0.76, 0.8},
      {"Thermal", 0.8, 0.9},
      {"Kinematics", 0.9, 1.0},
  }};
  return spans;
}

int planStageAt(double fraction)
{
  const auto& spans = planStageSpans();
  for (int i = kPlanStageCount - 1; i > 0; --i)
    if (fraction >= spans[static_cast<size_t>(i)].begin) return i;
  return 0;
}

DocumentPlan planDocument(const DocumentState& snapshot, const PluginRegistry& registry, Progress& progress,
                          const PlanDocumentOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  if (!snapshot.part || !snapshot.part->mesh || snapshot.part->mesh->empty())
    throw InputError("the project has no part to plan", "import a part into it first");
  const PlanSettings& settings = *snapshot.settings;
  progress.report(0.0, "checking the mesh");
  // A tilted part is planned in the build frame (world "up") and its results turned back.
  const PlacementFrame frame(snapshot.part->T_world_part);
  const TriangleMesh buildMesh = frame.identity() ? TriangleMesh() : frame.toBuild(*snapshot.part->mesh);
  const TriangleMesh& mesh = frame.identity() ? *snapshot.part->mesh : buildMesh;
  const MeshReport report = validateMesh(mesh);
  progress.checkCancel();

  PlanRequest request(mesh, report);
  // The build frame differs from the world by a translation; the substrate plane is stored in the world.
  request.substrateZ = snapshot.substrate->planeZ - snapshot.part->T_world_part.translation().z();
  request.substrate = substrateInBuildFrame(*snapshot.substrate, snapshot.part->T_world_part);
  request.lowerLoopOverride = snapshot.part->lowerBoundaryOverride;
  if (!frame.identity() && request.lowerLoopOverride >= 0)
    request.lowerLoopOverride = PlacementFrame::loopIndexInBuild(
        validateMesh(*snapshot.part->mesh).boundaryLoops, report.boundaryLoops, request.lowerLoopOverride);
  request.decomposerId = settings.decomposerId;
  request.closureFinderId = settings.closureFinderId;
  request.params = settings.params;
  request.midSurfaceOfSolid = options.midSurfaceOfSolid;
  SubProgress planProgress(progress, 0.0, kPlanShare, "");
  PlanOutput plan = planOrAdvise(registry, request, planProgress);
  if (!frame.identity()) {
    frame.toPart(plan.spiral.trajectory);
    frame.toPart(plan.generatrices);
    plan.closure.point = frame.pointToPart(plan.closure.point);
  }

  DocumentPlan out;
  out.feasible = plan.feasible();
  out.depositSummary = plan.deposits.summary();
  if (!out.feasible) {
    SubProgress adviceProgress(progress, kPlanShare, kPlanShare, "looking for a change that plans it");
    out.advice = adviseChange(registry, request, &plan, adviceProgress);
  }
  out.warnings = plan.warnings;
  out.summary = plan.solid ? plan.solid->summary() + "; " + summaryLine(plan) : summaryLine(plan);
  out.windowViolations = plan.spiral.report.violations.size();
  out.limitViolations = plan.process.violations.size();

  Results& r = out.results;
  auto field = std::make_shared<FieldResult>();
  field->kind = plan.fieldKind;
  field->source = plan.hasClosure ? "heat-method geodesic distance from the base edge"
                                  : "harmonic field, 0 on the base edge and 1 on the upper edge";
  // A solid's field lives on its mid-surface, whose vertices are not the part's: not drawn.
  if (!plan.solid) field->values = std::move(plan.field);
  r.setField(std::move(field), std::make_shared<const FieldStageReport>(fieldStageReport(plan)));

  // The reports count the generatrices, which move into the results next.
  auto generatricesReport = std::make_shared<const GeneratricesStageReport>(generatricesStageReport(plan));
  auto spiralReport =
      std::make_shared<const SpiralStageReport>(spiralStageReport(plan, settings.decomposerId));
  Generatrices lines = std::move(plan.generatrices);
  if (plan.hasClosure && !lines.hasClosurePoint) {
    lines.hasClosurePoint = true;
    lines.closurePoint = plan.closure.point;
  }
  r.setGeneratrices(std::make_shared<const Generatrices>(std::move(lines)), std::move(generatricesReport));

  // The spiral stage holds geometry and heights only: its speeds belong to the process stage,
  // which process edits drop on their own.
  auto processed = std::make_shared<const Trajectory>(std::move(plan.spiral.trajectory));
  auto geometry = std::make_shared<Trajectory>(*processed);
  for (TrajectoryPoint& p : geometry->points) p.travelSpeed = p.wireFeed = 0.0;
  r.setSpiral(std::move(geometry), std::move(spiralReport));
  r.setProcess(std::move(processed),
               std::make_shared<const ProcessStageReport>(processStageReport(plan.process)));

  // Off, the section is not read: a plan without the stage is the plan it always was.
  const ParamSet thermalValues = settings.section(PlanSettings::kThermalSection);
  if (thermalStageEnabled(thermalValues)) {
    ThermalStageSettings thermal = thermalStageSettingsFrom(thermalValues);
    thermal.windowMin = readPlanSections(settings.params).spiral.hMin;
    SubProgress thermalProgress(progress, kPlanShare, kThermalShare, "thermal");
    ThermalStageOutput heat = runThermalStage(
        *r.process, thermal, processSettingsFrom(settings.section(PlanSettings::kProcessSection)),
        thermalProgress);
    if (heat.result->replanned && heat.report->revolutionsAdded.value_or(0) > 0) {
      Trajectory thinned = *heat.result->replanned;
      if (!frame.identity()) frame.toBuild(thinned);
      NullProgress quiet;
      const DepositCheckReport check =
          checkPlannedDeposits(registry, request, thinned, !plan.solid.has_value(), quiet);
      ThermalStageReport judged = *heat.report;
      judged.depositCheck = depositCheckRecord(check);
      heat.report = std::make_shared<const ThermalStageReport>(std::move(judged));
      out.feasible = out.feasible && check.feasible;
      out.depositSummary = check.summary();
    }
    r.setThermal(std::move(heat.result), std::move(heat.report));
  }
  const Trajectory& motionPath = r.thermal && r.thermal->replanned ? *r.thermal->replanned : *r.process;
  SubProgress kinematicsProgress(progress, kThermalShare, 1.0, "kinematics");
  DocumentMotion kinematics = solveDocumentMotion(snapshot, motionPath, request.substrateZ,
                                                  kinematicsProgress, options.resolveCollisions);
  out.warnings.insert(out.warnings.end(), kinematics.warnings.begin(), kinematics.warnings.end());
  out.motionOk = !snapshot.cell || kinematics.ok;
  if (kinematics.result)
    r.setKinematics(std::move(kinematics.result),
                    std::make_shared<const KinematicsStageReport>(
                        KinematicsStageReport{*kinematics.report, kinematics.seconds}));

  out.report = mergedPlanReport(r);
  if (out.advice) out.report["advice"] = adviceJson(*out.advice);
  out.output = std::move(plan);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<SettingsProblem> settingsProblems(const PlanSettings& settings)
{
  std::vector<SettingsProblem> out;
  // Each section on its own, so that a problem in one does not hide one in the other.
  for (const SettingsSection& section : planSections()) {
    const std::string name(section.name);
    try {
      readPlanSections({{name, settings.section(name)}});
    } catch (const Error& e) {
      out.push_back({e.what(), e.hint()});
    }
  }
  try {
    thermalStageSettingsFrom(settings.section(PlanSettings::kThermalSection));
  } catch (const Error& e) {
    out.push_back({e.what(), e.hint()});
  }
  return out;
}

std::optional<Stage> storePlanResults(Document& doc, const DocumentState& snapshot, const Results& computed)
{
  const std::optional<Stage> stale = firstInvalidatedStage(snapshot, doc.state());
  Results r = computed;
  if (stale) r.invalidateFrom(*stale);
  if (stale && stageIndex(*stale) <= stageIndex(Stage::Field)) return stale;
  // The export stage of the document was computed from the previous plan.
  doc.setResults(std::move(r));
  if (stale && stageIndex(*stale) > stageIndex(Stage::Kinematics)) return std::nullopt;
  return stale;
}

}  // namespace spira
