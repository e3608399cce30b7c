// The optional thermal stage of a plan: off, a plan is what it was; on, it holds what a direct
// thermal study of the process stage's path gives; cancelled while it runs, nothing is stored.
#include <atomic>
#include <cstring>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "builtin_plugins.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/document/document.h"
#include "spira/document/plan_report.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/path/dwell.h"
#include "spira/pipeline/document_plan.h"
#include "spira/pipeline/planned_path.h"
#include "spira/pipeline/thermal_stage.h"
#include "spira/planning/plan_schemas.h"
#include "spira/thermal/thermal_replan.h"

namespace spira {
namespace {

// A short open wall: twenty-odd revolutions, a few minutes of welding.
DocumentState smallWall()
{
  Document doc;
  Part part;
  part.name = "wall";
  part.mesh = std::make_shared<const TriangleMesh>(makeOpenCylinder(20.0, 40.0, 48, 20));
  doc.setPart(part);
  return doc.state();
}

void enableThermal(Document& doc)
{
  doc.setParam(PlanSettings::kThermalSection, "enabled", true);
  doc.setParam(PlanSettings::kThermalSection, "frames", ParamValue(std::int64_t{40}));
  doc.setParam(PlanSettings::kThermalSection, "interpass_max", 300.0);
  doc.setParam(PlanSettings::kThermalSection, "remedy_heat", false);  // drawn and counted only
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(ThermalStage, OffByDefaultAndThePlanIsUnchanged)
{
  Document doc(smallWall());
  NullProgress progress;
  const DocumentPlan plain = planDocument(doc.state(), builtinRegistry(), progress);
  EXPECT_FALSE(plain.results.thermal || plain.results.reports.thermal);
  EXPECT_FALSE(plain.report.contains("thermal"));
  // Values in the section do nothing while it is off, even ones the stage would refuse.
  doc.setParam(PlanSettings::kThermalSection, "power", 0.0);
  doc.setParam(PlanSettings::kThermalSection, "interpass_max", 250.0);
  const DocumentPlan again = planDocument(doc.state(), builtinRegistry(), progress);
  EXPECT_FALSE(again.results.thermal);
  EXPECT_EQ(*again.results.process, *plain.results.process);
  nlohmann::json a = again.report, b = plain.report;  // wall times differ from run to run
  a.erase("timings_s"), b.erase("timings_s");
  EXPECT_EQ(a, b);
}

TEST(ThermalStage, HoldsWhatADirectStudyOfTheProcessPathGives)
{
  Document doc(smallWall());
  enableThermal(doc);
  NullProgress progress;
  const DocumentPlan plan = planDocument(doc.state(), builtinRegistry(), progress);
  ASSERT_TRUE(plan.results.thermal && plan.results.reports.thermal && plan.results.process);
  const ThermalStageResult& t = *plan.results.thermal;
  const ThermalStageReport& rep = *plan.results.reports.thermal;

  const ThermalStageSettings settings = thermalStageSettingsFrom(doc.settings()->section("thermal"));
  const ThermalStudySettings study = thermalStudySettingsFor(*plan.results.process, settings,
                                                             beadWidthOf(doc.settings()->section("process")));
  EXPECT_DOUBLE_EQ(study.mesh.thickness, 5.2);
  const ThermalStudy direct = runThermalStudy(*plan.results.process, study, progress);
  ASSERT_EQ(t.pointCount(), plan.results.process->size());
  EXPECT_TRUE(sameBits(t.peak, direct.result.peak));
  EXPECT_TRUE(sameBits(t.interpass, direct.result.interpass));
  EXPECT_TRUE(sameBits(t.timeAboveMelt, direct.result.timeAboveMelt));
  EXPECT_TRUE(sameBits(t.bond, direct.bond));
  EXPECT_TRUE(sameBits(t.poolLength, direct.poolLength));
  EXPECT_EQ(t.nodes, direct.mesh.nodes);
  EXPECT_EQ(t.triangles.size(), direct.mesh.triangles.size());
  EXPECT_EQ(rep.riskPoints, direct.riskPoints);
  EXPECT_EQ(rep.nodes, direct.result.nodes);
  EXPECT_EQ(rep.steps, direct.result.steps);
  EXPECT_DOUBLE_EQ(rep.energyIn, direct.result.energy.in);
  EXPECT_DOUBLE_EQ(rep.maxPeak, *std::max_element(direct.result.peak.begin(), direct.result.peak.end()));
  EXPECT_EQ(rep.material, "G3Si1");
  EXPECT_EQ(rep.interpassLimit, 300.0);
  EXPECT_EQ(rep.pointsOverLimit,
            std::count_if(t.interpass.begin(), t.interpass.end(), [](double v) { return v > 300.0; }));
  // The frames: about as many as asked, the last with every node born, within half a step.
  ASSERT_EQ(t.frames.size(), direct.frames.times.size());
  EXPECT_GE(t.frames.size(), 40u);
  const auto& last = direct.frames.values.back();
  for (size_t n = 0; n < last.size(); n += 97)
    EXPECT_NEAR(t.frames.at(t.frames.size() - 1, n), last[n], 0.5 * t.frames.step + 1e-3) << n;
  // The point's node is where the torch laid it.
  for (size_t i = 0; i < t.pointCount(); i += 50)
    EXPECT_LT(
        (t.nodes[static_cast<size_t>(t.pointNode[i])] - plan.results.process->points[i].position).norm(),
        1e-9)
        << i;
  EXPECT_TRUE(plan.report.contains("thermal"));
  EXPECT_EQ(plan.report["thermal"]["n_risk_points"], rep.riskPoints);
}

// With the remedy on, the stage re-plans the path to the limit: the robot and the program then
// follow the slower path, which meets the limit when simulated again on its own.
TEST(ThermalStage, ReplansToTheInterpassLimitAndTheMotionFollows)
{
  Document doc(smallWall());
  enableThermal(doc);
  NullProgress progress;
  const DocumentPlan plain = planDocument(doc.state(), builtinRegistry(), progress);
  ASSERT_TRUE(plain.results.reports.thermal);
  const double hottest = plain.results.reports.thermal->maxInterpass;
  const double limit = 20.0 + 0.8 * (hottest - 20.0);
  doc.setParam(PlanSettings::kThermalSection, "interpass_max", limit);
  doc.setParam(PlanSettings::kThermalSection, "remedy_heat", true);
  const DocumentPlan plan = planDocument(doc.state(), builtinRegistry(), progress);
  ASSERT_TRUE(plan.results.thermal && plan.results.reports.thermal);
  const ThermalStageReport& rep = *plan.results.reports.thermal;
  ASSERT_TRUE(rep.limitMet.has_value());
  EXPECT_TRUE(*rep.limitMet);
  EXPECT_EQ(rep.revolutionsAdded, 0);
  EXPECT_GT(rep.buildTimeAdded.value_or(0.0), 0.0);
  EXPECT_LE(rep.maxInterpass, limit);
  ASSERT_TRUE(plan.results.thermal->replanned);
  const Trajectory& slower = *plan.results.thermal->replanned;
  ASSERT_EQ(slower.size(), plan.results.process->size());
  EXPECT_EQ(*plannedPathOf(plan.results).trajectory, slower);

  ThermalStageSettings settings = thermalStageSettingsFrom(doc.settings()->section("thermal"));
  ThermalStudySettings study =
      thermalStudySettingsFor(slower, settings, beadWidthOf(doc.settings()->section("process")));
  study.solver.powerPerWireFeed = powerPerWireFeedOf(*plan.results.process, study.solver.power);
  const ThermalStudy again = runThermalStudy(slower, study, progress);
  double worst = 0.0;
  for (size_t i = 0; i < slower.size(); ++i)
    if (slower.points[i].revolution > 0) worst = std::max(worst, again.result.interpass[i]);
  EXPECT_LE(worst, limit);
  EXPECT_NEAR(again.result.energy.in, plain.results.reports.thermal->energyIn, 1e-9 * again.result.energy.in);
}

TEST(ThermalStage, CancelledWhileItRunsLeavesThePreviousResults)
{
  Document doc(smallWall());
  NullProgress none;
  storePlanResults(doc, doc.state(), planDocument(doc.state(), builtinRegistry(), none).results);
  const Results before = doc.results();
  ASSERT_TRUE(before.process);
  enableThermal(doc);
  doc.setResults(before);  // the previous plan, as if the user enabled the stage and pressed Plan
  std::atomic<bool> sawThermal{false};
  CallbackProgress* self = nullptr;
  CallbackProgress progress([&](double fraction, std::string_view) {
    if (fraction > 0.8 && fraction < 0.9) {
      sawThermal = true;
      self->cancel();
    }
  });
  self = &progress;
  const DocumentState snapshot = doc.state();
  EXPECT_THROW(planDocument(snapshot, builtinRegistry(), progress), Cancelled);
  EXPECT_TRUE(sawThermal);
  EXPECT_EQ(doc.results(), before);
  EXPECT_FALSE(doc.results().thermal);
}

TEST(ThermalStage, ItsProgressSpanSitsBetweenProcessAndKinematics)
{
  const auto& spans = planStageSpans();
  EXPECT_STREQ(spans[kThermalPlanStage].label, "Thermal");
  EXPECT_EQ(spans[kThermalPlanStage - 1].end, spans[kThermalPlanStage].begin);
  EXPECT_EQ(spans[kThermalPlanStage].end, spans[kThermalPlanStage + 1].begin);
  EXPECT_STREQ(spans[kThermalPlanStage + 1].label, "Kinematics");
  EXPECT_EQ(planStageAt(0.85), kThermalPlanStage);
}

TEST(ThermalStage, ARePlannedPathIsWhatTheViewsAndExportFollow)
{
  Results r;
  auto process = std::make_shared<Trajectory>();
  process->points.resize(3);
  r.setProcess(process);
  EXPECT_EQ(processPathOf(r), r.process);
  EXPECT_EQ(plannedPathOf(r).trajectory, r.process);
  auto thermal = std::make_shared<ThermalStageResult>();
  r.setThermal(thermal);
  EXPECT_EQ(processPathOf(r), r.process);  // simulated, not re-planned
  auto replanned = std::make_shared<Trajectory>();
  replanned->points.resize(5);
  thermal->replanned = replanned;
  EXPECT_EQ(processPathOf(r), replanned);
  EXPECT_EQ(plannedPathOf(r).trajectory, replanned);
}

TEST(ThermalStage, BadSettingsAreNamed)
{
  ParamSet values;
  values.set("enabled", true);
  values.set("power", 0.0);
  EXPECT_THROW(thermalStageSettingsFrom(values), InputError);
  values.set("voltage", 20.0);
  values.set("current", 150.0);
  EXPECT_DOUBLE_EQ(thermalStageSettingsFrom(values).study.solver.power, 0.8 * 20.0 * 150.0);
  // The arc is half the bead wide unless set; radiation off unless an emissivity is given.
  const Trajectory none;
  EXPECT_DOUBLE_EQ(thermalStudySettingsFor(none, thermalStageSettingsFrom(values), 5.2).solver.sourceRadius,
                   2.6);
  EXPECT_EQ(thermalStageSettingsFrom(values).study.solver.material.emissivity, 0.0);
  values.set("arc_radius", 3.0);
  values.set("emissivity", 0.6);
  EXPECT_DOUBLE_EQ(thermalStudySettingsFor(none, thermalStageSettingsFrom(values), 5.2).solver.sourceRadius,
                   3.0);
  EXPECT_DOUBLE_EQ(thermalStageSettingsFrom(values).study.solver.material.emissivity, 0.6);
  values.set("material", std::string("unobtainium"));
  EXPECT_THROW(thermalStageSettingsFrom(values), InputError);
  EXPECT_FALSE(thermalStageEnabled(ParamSet()));
  EXPECT_TRUE(thermalSchema().selfCheck().empty());
}

// With only the dwell remedy, the stage adds waits before the hot revolutions: the path's points
// and speeds are the plan's, the waits ride in its dwell channel, and the report says their cost.
TEST(ThermalStage, DwellsBeforeTheHotRevolutionsWhenOnlyDwellIsChosen)
{
  Document doc(smallWall());
  enableThermal(doc);
  NullProgress progress;
  const DocumentPlan plain = planDocument(doc.state(), builtinRegistry(), progress);
  ASSERT_TRUE(plain.results.reports.thermal);
  const double limit = 20.0 + 0.8 * (plain.results.reports.thermal->maxInterpass - 20.0);
  doc.setParam(PlanSettings::kThermalSection, "interpass_max", limit);
  doc.setParam(PlanSettings::kThermalSection, "remedy_heat", false);
  doc.setParam(PlanSettings::kThermalSection, "remedy_dwell", true);
  const DocumentPlan plan = planDocument(doc.state(), builtinRegistry(), progress);
  ASSERT_TRUE(plan.results.thermal && plan.results.reports.thermal);
  const ThermalStageReport& rep = *plan.results.reports.thermal;
  ASSERT_TRUE(rep.limitMet.has_value());
  EXPECT_TRUE(*rep.limitMet) << rep.whyNotMet.value_or("");
  EXPECT_LE(rep.maxInterpass, limit);
  EXPECT_EQ(rep.remediesApplied, std::vector<std::string>{"dwell"});
  ASSERT_TRUE(rep.dwells.has_value());
  EXPECT_GT(*rep.dwells, 0);
  EXPECT_NEAR(rep.buildTimeAdded.value_or(0.0), rep.dwellTime.value_or(-1.0), 1e-6);
  ASSERT_TRUE(plan.results.thermal->replanned);
  const Trajectory& waiting = *plan.results.thermal->replanned;
  EXPECT_EQ(waiting.points, plan.results.process->points);
  EXPECT_TRUE(hasDwell(waiting));
  EXPECT_EQ(*plannedPathOf(plan.results).trajectory, waiting);
  EXPECT_EQ(plan.report["thermal"]["dwells"], *rep.dwells);
}

// The deposit remedy on a path fed at a constant travel speed: the thinner band feeds less wire, so
// less arc power at the same speed, and it cools. The thinned path is what the plan executes: the
// deposit check judges it again, and that verdict is the plan's.
TEST(ThermalStage, ThinnerBandIsJudgedAgainByTheDepositCheck)
{
  Document doc(smallWall());
  enableThermal(doc);
  doc.setParam(PlanSettings::kProcessSection, "process", std::string("constant-ts"));
  doc.setParam(PlanSettings::kSpiralSection, "h_min", 1.0);
  NullProgress progress;
  const DocumentPlan plain = planDocument(doc.state(), builtinRegistry(), progress);
  ASSERT_TRUE(plain.feasible);
  ASSERT_TRUE(plain.results.reports.thermal);
  const double limit = 20.0 + 0.85 * (plain.results.reports.thermal->maxInterpass - 20.0);
  doc.setParam(PlanSettings::kThermalSection, "interpass_max", limit);
  doc.setParam(PlanSettings::kThermalSection, "remedy_deposit", true);
  const DocumentPlan plan = planDocument(doc.state(), builtinRegistry(), progress);
  ASSERT_TRUE(plan.results.thermal && plan.results.reports.thermal);
  const ThermalStageReport& rep = *plan.results.reports.thermal;
  EXPECT_TRUE(rep.limitMet.value_or(false)) << rep.whyNotMet.value_or("");
  EXPECT_EQ(rep.remediesApplied, std::vector<std::string>{"deposit"});
  ASSERT_GT(rep.revolutionsAdded.value_or(0), 0);
  ASSERT_TRUE(plan.results.thermal->replanned);
  const Trajectory& thinned = *plan.results.thermal->replanned;
  size_t perRevolution = 0;
  for (const TrajectoryPoint& p : plan.results.process->points) perRevolution += p.revolution == 1;
  EXPECT_EQ(thinned.size(), plan.results.process->size() + size_t(*rep.revolutionsAdded) * perRevolution);
  ASSERT_TRUE(rep.depositCheck.has_value());
  EXPECT_TRUE(rep.depositCheck->feasible) << rep.depositCheck->summary;
  EXPECT_GE(rep.depositCheck->heightMin, 1.0 - 0.01);
  EXPECT_LT(rep.depositCheck->heightMean, plain.results.reports.spiral->depositCheck.heightMean - 0.05);
  EXPECT_TRUE(plan.feasible);
  EXPECT_EQ(plan.report["deposit_check"]["points_checked"], rep.depositCheck->pointsChecked);
  EXPECT_EQ(plan.report["feasible"], true);
  const std::optional<PlanReportSummary> summary = planSummaryOf(plan.results);
  ASSERT_TRUE(summary);
  EXPECT_EQ(summary->depositHeightMin, rep.depositCheck->heightMin);
}

}  // namespace
}  // namespace spira
