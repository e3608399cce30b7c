// MainWindow: planning the part (the Plan menu) and showing the plan's results.
#include <QAction>
#include <QDockWidget>
#include <QLocale>

#include "spira/pipeline/document_plan.h"
#include "spira/pipeline/planned_path.h"
#include "spira/pipeline/thermal_schema.h"
#include "spira/plugin/strategy_name.h"
#include "spira/ui/charts/joint_chart.h"
#include "spira/ui/charts/process_chart.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/panels/stage_progress.h"
#include "spira/ui/panels/thermal_panel.h"
#include "spira/ui/views/path_inspector.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/spiral_layer.h"
#include "spira/ui/window/main_window.h"

namespace spira::ui {

namespace {

QString fromStd(const std::string& s)
{
  return QString::fromStdString(s);
}

}  // namespace

void MainWindow::plan()
{
  if (planning_) return;
  // Refusals are outcomes too: whoever waits on planFinished() hears of them.
  auto refuse = [this](const QString& message, const QString& hint) {
    reportError(tr("Plan"), message, hint);
    TaskOutcome out;
    out.status = TaskOutcome::Status::Failed;
    out.message = message;
    out.hint = hint;
    emit planFinished(out);
  };
  if (busy()) {
    refuse(tr("Cannot plan while another task runs."), tr("Wait for it to finish or cancel it."));
    return;
  }
  if (!doc_.part() || !doc_.part()->mesh || doc_.part()->mesh->empty()) {
    refuse(tr("There is no part to plan."), tr("Import a part first (File > Import Part...)."));
    return;
  }
  const auto snapshot = std::make_shared<const DocumentState>(doc_.snapshot());
  auto result = std::make_shared<DocumentPlan>();
  const PlanSettings& settings = *snapshot->settings;
  log_->info(tr("Planning %1 (%2 strategy) ...")
                 .arg(fromStd(snapshot->part->name), fromStd(strategyName(settings.decomposerId))));
  planning_ = true;
  actions_.plan->setEnabled(false);
  actions_.cancelPlan->setEnabled(true);
  planPanel_->progress()->start(thermalStageEnabled(settings.section(PlanSettings::kThermalSection)));
  const PluginRegistry& registry = registry_;  // outlives the window, and so the worker
  tasks_->start(
      tr("Planning %1").arg(fromStd(snapshot->part->name)),
      [snapshot, result, &registry](Progress& progress) {
        *result = planDocument(*snapshot, registry, progress);
      },
      [this, snapshot, result](const TaskOutcome& outcome) { finishPlan(outcome, *snapshot, *result); },
      TaskRunner::Display::Signals);
}

void MainWindow::cancelPlan()
{
  if (planning_) tasks_->cancel();
}

void MainWindow::finishPlan(const TaskOutcome& outcome, const DocumentState& snapshot,
                            const DocumentPlan& result)
{
  planning_ = false;
  actions_.plan->setEnabled(true);
  actions_.cancelPlan->setEnabled(false);
  planPanel_->progress()->stop();
  if (outcome.status == TaskOutcome::Status::Cancelled) {
    log_->info(tr("Planning cancelled; the previous results are unchanged."));
  } else if (!outcome.succeeded()) {
    reportError(tr("Planning failed"), outcome.message, outcome.hint);
  } else {
    for (const std::string& w : result.warnings) log_->warning(fromStd(w));
    const std::optional<Stage> dropped = storePlanResults(doc_, snapshot, result.results);
    if (dropped && *dropped == Stage::Field) {
      log_->warning(tr("The part changed while planning: the plan was discarded."),
                    tr("Press Plan (F5) again."));
    } else {
      if (dropped)
        log_->warning(tr("Settings changed while planning: the results from the %1 stage on were dropped.")
                          .arg(QString::fromUtf8(stageName(*dropped))),
                      tr("Press Plan (F5) again to bring them up to date."));
      log_->info(tr("Planned in %1 s: %2.")
                     .arg(QLocale().toString(result.seconds, 'f', 2), fromStd(result.summary)));
      if (!result.feasible)
        log_->warning(tr("The plan is infeasible: %1.").arg(fromStd(result.depositSummary)),
                      tr("The points are listed below (click one to select it). Spira's advice: %1.")
                          .arg(fromStd(result.advice ? result.advice->text(false) : std::string())));
    }
  }
  emit planFinished(outcome);
}

void MainWindow::refreshResults()
{
  const Results& r = doc_.results();
  const Transform placement = doc_.part() ? doc_.part()->T_world_part : Transform::Identity();
  view_->showResults(r, placement);
  // A new spiral is what the user planned for: show it over a faint part. Without results the
  // part goes back to plain metal.
  const bool hasSpiral = r.spiral != nullptr;
  if (hasSpiral && !hadSpiral_) {
    view_->setPartStyle(PartStyle::Transparent);
    display_->raise();
  } else if (!hasSpiral && (view_->partStyle() != PartStyle::Field || !r.field)) {
    view_->setPartStyle(PartStyle::Shaded);
  }
  hadSpiral_ = hasSpiral;
  const std::shared_ptr<const Trajectory> processed = processPathOf(r);
  const Trajectory* path = processed ? processed.get() : r.spiral.get();
  chart_->setPath(path, processed != nullptr, planWindow(r));
  inspector_->setResults(r, placement);
  jointChart_->setKinematics(r.kinematics);
  thermal_->setResults(r);
  // New thermal results are what the user enabled the stage for: bring their dock forward.
  const bool hasThermal = r.thermal != nullptr;
  if (hasThermal && !hadThermal_) {
    thermal_->show();
    thermal_->raise();
  }
  hadThermal_ = hasThermal;
  display_->resultsChanged();
}

}  // namespace spira::ui
