// Planning a large part: the window stays live (no modal dialog, the 3D view keeps rotating),
// the Plan dock shows progress per stage, and Cancel returns at once leaving the previous
// results as they were. Plus the error and infeasible outcomes in the messages panel.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <set>
#include <vector>

#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QTimer>
#include <QToolButton>

#include <gtest/gtest.h>

#include <vtkCamera.h>
#include <vtkRenderer.h>
#include <nlohmann/json.hpp>
#include "builtin_plugins.h"

#include "spira/document/document.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/pipeline/document_plan.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/param_field.h"
#include "spira/ui/panels/param_panel.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/panels/stage_progress.h"
#include "spira/ui/views/path_inspector.h"
#include "spira/ui/views/point_selection.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/spiral_layer.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::LogLevel;
using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;
using spira::ui::TaskOutcome;

void setPart(Document& doc, TriangleMesh mesh, const std::string& name)
{
  Part part;
  part.name = name;
  part.mesh = std::make_shared<const TriangleMesh>(std::move(mesh));
  doc.setPart(std::move(part), "Import Part");
}

QString lastLog(MainWindow& w)
{
  return w.logPanel()->text(w.logPanel()->count() - 1);
}

TEST(PlanCancel, CancelReturnsAtOnceAndKeepsThePreviousResults)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  // A fine hemisphere: planning it takes seconds, most of it in sparse factorisations.
  setPart(doc, makeHemisphere(80.0, 720, 240), "large dome");
  const size_t triangles = doc.part()->mesh->faceCount();

  QElapsedTimer full;
  full.start();
  ASSERT_TRUE(planAndWait(w));
  const double fullSeconds = full.elapsed() / 1000.0;
  const Results before = doc.results();
  ASSERT_TRUE(before.spiral) << w.lastErrorMessage().toStdString();
  const auto revision = doc.revision();

  // Plan again and watch the window while the worker runs: a timer on the GUI thread keeps
  // ticking (nothing there waits for the worker).
  QTimer ticker;
  QElapsedTimer sinceTick;
  qint64 longestGap = 0;
  int ticks = 0;
  ticker.setInterval(10);
  QObject::connect(&ticker, &QTimer::timeout, [&] {
    if (ticks++ > 0) longestGap = std::max(longestGap, sinceTick.elapsed());
    sinceTick.restart();
  });
  bool finished = false;
  TaskOutcome outcome;
  QObject::connect(&w, &MainWindow::planFinished, [&](const TaskOutcome& o) {
    finished = true;
    outcome = o;
  });
  w.actions().plan->trigger();
  ticker.start();
  sinceTick.start();
  ticks = 0;
  ASSERT_TRUE(w.planning());
  EXPECT_FALSE(w.actions().plan->isEnabled());
  EXPECT_TRUE(w.actions().cancelPlan->isEnabled());
  ui::StageProgress* progress = w.planPanel()->progress();
  EXPECT_TRUE(progress->isVisible());
  EXPECT_TRUE(progress->running());
  EXPECT_TRUE(progress->cancelButton()->isEnabled());
  // Reports reach the stage bars while the worker runs.
  std::vector<std::pair<double, QString>> reports;
  QObject::connect(w.taskRunner(), &ui::TaskRunner::progressed,
                   [&](double f, const QString& stage) { reports.emplace_back(f, stage); });
  // Let it get well into the work (a third of a full plan), rotating the view meanwhile as a
  // user would.
  vtkCamera* camera = w.sceneView()->renderer()->GetActiveCamera();
  double before3[3];
  camera->GetPosition(before3);
  QElapsedTimer running;
  running.start();
  const double quietMs = 0.2 * fullSeconds * 1000.0;
  waitFor([&] { return finished || running.elapsed() > quietMs; }, 120000);
  ticker.stop();
  const qint64 gap = longestGap;
  // The Plan dock shows the stages while the 3D view still shows the previous plan.
  const QImage during = w.captureImage();
  EXPECT_GT(distinctColours(during, rectIn(w, progress)), 20);
  saveDocScreenshot(during, "plan-progress.png");
  int frames = 0;
  ASSERT_FALSE(waitFor(
                   [&] {
                     camera->Azimuth(3.0);
                     w.sceneView()->render();
                     ++frames;
                     return finished || running.elapsed() > 0.4 * fullSeconds * 1000.0;
                   },
                   120000) &&
               finished)
      << "the plan finished before it could be cancelled; use a larger part";
  EXPECT_EQ(QApplication::activeModalWidget(), nullptr);  // nothing blocks the window
  double after3[3];
  camera->GetPosition(after3);
  EXPECT_GT(std::abs(after3[0] - before3[0]) + std::abs(after3[1] - before3[1]), 1.0);
  ASSERT_FALSE(reports.empty());
  const int stage = progress->currentStage();
  EXPECT_EQ(stage, planStageAt(reports.back().first));
  for (int s = 0; s < stage; ++s) EXPECT_EQ(progress->stagePercent(s), 100) << s;
  std::cout << "[ measure  ] cancelling in stage " << stage << " at " << reports.back().first << " ("
            << reports.back().second.toStdString() << "), " << reports.size() << " progress polls\n";

  QElapsedTimer cancelTimer;
  cancelTimer.start();
  progress->cancelButton()->click();
  ASSERT_TRUE(waitFor([&] { return finished; }, 5000));
  const qint64 cancelMs = cancelTimer.elapsed();
  std::cout << "[ measure  ] " << triangles << " triangles: full plan " << fullSeconds
            << " s, cancel returned in " << cancelMs << " ms, longest event-loop gap while planning " << gap
            << " ms, " << frames << " frames rendered meanwhile\n";
  RecordProperty("cancel_ms", static_cast<int>(cancelMs));
  EXPECT_LT(cancelMs, 200);
  EXPECT_LT(gap, 250);  // the GUI thread never waited for the worker
  EXPECT_GT(frames, 0);
  EXPECT_EQ(outcome.status, TaskOutcome::Status::Cancelled);
  EXPECT_FALSE(w.planning());
  EXPECT_TRUE(w.actions().plan->isEnabled());
  EXPECT_FALSE(progress->isVisible());
  EXPECT_FALSE(progress->running());
  EXPECT_TRUE(lastLog(w).contains("cancelled"));
  EXPECT_EQ(doc.revision(), revision);
  EXPECT_EQ(doc.results().field, before.field);  // the very same values, not a recomputation
  EXPECT_EQ(doc.results().spiral, before.spiral);
  EXPECT_EQ(doc.results().process, before.process);
  EXPECT_EQ(w.sceneView()->spiralLayer().shownPointCount(), static_cast<long long>(before.process->size()));

  // The abandoned worker stops at its next cancellation check.
  QElapsedTimer stopTimer;
  stopTimer.start();
  ASSERT_TRUE(waitFor([&] { return w.taskRunner()->abandonedCount() == 0; }, 120000));
  std::cout << "[ measure  ] the cancelled worker itself stopped " << stopTimer.elapsed() + cancelMs
            << " ms after Cancel\n";
}

TEST(PlanCancel, ContradictorySettingsFailWithTheHintAndInfeasiblePlansAreFlagged)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  // No part: the Plan action says what to do.
  ASSERT_TRUE(planAndWait(w));
  EXPECT_EQ(w.lastErrorMessage(), "There is no part to plan.");
  EXPECT_FALSE(w.lastErrorHint().isEmpty());
  EXPECT_EQ(w.logPanel()->level(w.logPanel()->count() - 1), LogLevel::Error);

  // A cylinder whose top is cut at a slant: its generatrices range from 40 to 80 mm, far more
  // spread than a +/-10 % window can absorb (thesis Eq. 3.6).
  TriangleMesh slanted = makeOpenCylinder(30.0, 60.0, 64, 24);
  for (Vec3& v : slanted.vertices) v.z() *= 1.0 + v.x() / 90.0;
  setPart(doc, std::move(slanted), "slanted tube");

  // h outside [h_min, h_max]: an InputError whose hint reaches the messages panel.
  doc.setParam("spiral", "h_min", 2.1);
  ASSERT_TRUE(planAndWait(w));
  EXPECT_FALSE(doc.results().spiral);
  EXPECT_TRUE(w.lastErrorMessage().contains("outside the window")) << w.lastErrorMessage().toStdString();
  EXPECT_FALSE(w.lastErrorHint().isEmpty());
  EXPECT_EQ(w.logPanel()->level(w.logPanel()->count() - 1), LogLevel::Error);
  EXPECT_TRUE(lastLog(w).contains("Hint: " + w.lastErrorHint()));

  w.planPanel()->panel("spiral")->field("h_min")->resetButton()->click();
  ASSERT_TRUE(planAndWait(w));
  ASSERT_TRUE(doc.results().spiral) << w.lastErrorMessage().toStdString();
  ASSERT_TRUE(doc.results().reports.spiral);
  const SpiralStageReport& report = *doc.results().reports.spiral;
  EXPECT_FALSE(report.feasible);
  EXPECT_GT(report.violations, 0);
  EXPECT_EQ(w.planPanel()->verdictLabel()->property("feasible"), QVariant(false));
  EXPECT_TRUE(w.planPanel()->verdictLabel()->text().contains("Infeasible plan"));
  ui::SpiralLayer& spiral = w.sceneView()->spiralLayer();
  EXPECT_EQ(spiral.violationCount(), report.violations);  // the same rule as the planner's
  EXPECT_EQ(spiral.shownViolationCount(), spiral.violationCount());
  bool warned = false;
  QString advice;
  for (int i = 0; i < w.logPanel()->count(); ++i)
    if (w.logPanel()->level(i) == LogLevel::Warning && w.logPanel()->text(i).contains("infeasible")) {
      warned = true;
      advice = w.logPanel()->text(i);
    }
  EXPECT_TRUE(warned);
  // The advice was planned, not guessed: the change found feasible, or each change tried and why
  // it failed (a wider window than +/-50 % is not advice).
  EXPECT_TRUE(advice.contains("Spira's advice: ")) << advice.toStdString();
  EXPECT_TRUE(advice.contains("planned and checked feasible") ||
              advice.contains("no change of window or strategy"))
      << advice.toStdString();
  // The offending points are listed, each message selecting its point when clicked.
  auto* list = w.logPanel()->findChild<QListWidget*>();
  ASSERT_NE(list, nullptr);
  const double hMin = report.hMin, hMax = report.hMax, tol = report.heightTolerance;
  // Two lists: the planned heights outside the window, then the points the deposit check rejects.
  std::set<long long> rejected;
  for (const DepositFlagRecord& f : report.depositCheck.flaggedPoints) rejected.insert(f.point);
  int listed = 0, listedRejected = 0;
  for (int row = 0; row < list->count(); ++row) {
    const QVariant v = list->item(row)->data(ui::PathInspector::kPointRole);
    if (!v.isValid()) continue;
    const long long i = v.toLongLong();
    ASSERT_GE(i, 0);
    ASSERT_LT(static_cast<size_t>(i), doc.results().process->size());
    const double h = doc.results().process->points[static_cast<size_t>(i)].height;
    if (list->item(row)->text().contains("outside the window")) {
      ++listed;
      EXPECT_TRUE(h < hMin - tol || h > hMax + tol) << "point " << i << " at " << h << " mm";
    } else {
      ++listedRejected;
      EXPECT_EQ(rejected.count(i), 1u) << list->item(row)->text().toStdString();
    }
    EXPECT_TRUE(list->item(row)->text().contains("Point " + QLocale().toString(i) + " ("))
        << list->item(row)->text().toStdString();
    emit list->itemClicked(list->item(row));
    EXPECT_EQ(w.pointSelection()->index(), i);
  }
  EXPECT_EQ(listed, std::min<std::int64_t>(ui::PathInspector::kMaxListedPoints, report.violations));
  EXPECT_EQ(listedRejected,
            std::min<int>(ui::PathInspector::kMaxListedPoints, static_cast<int>(rejected.size())));
  EXPECT_GT(listedRejected, 0);
  const QImage image = w.captureImage();
  EXPECT_GT(distinctColours(image, sceneRect(w)), 400);
  saveDocScreenshot(image, "plan-infeasible.png");
}

}  // namespace
}  // namespace spira::test
