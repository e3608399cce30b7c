// The thermal stage in the desktop app, as a process engineer uses it: open the sample dome, switch
// the stage on in the Plan dock's Thermal tab with an interpass limit, plan (the stage runs in the
// background plan), colour the spiral by interpass temperature and by collapse risk, click a risk
// message to chart that point's temperature, colour the part by its temperature part-way through
// the build, save and reopen the project, and cancel a plan while the thermal stage runs. Each view
// writes a documentation screenshot.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QTabWidget>
#include <QToolButton>

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkTable.h>
#include <vtkVariant.h>

#include "builtin_plugins.h"
#include "spira/document/document.h"
#include "spira/document/project_file.h"
#include "spira/ui/charts/probe_chart.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/param_field.h"
#include "spira/ui/panels/param_panel.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/panels/stage_progress.h"
#include "spira/ui/panels/thermal_panel.h"
#include "spira/ui/views/path_inspector.h"
#include "spira/ui/views/point_selection.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/spiral_layer.h"
#include "spira/ui/views/thermal_layer.h"
#include "spira/ui/views/thermal_risk_zones.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;

constexpr double kLimit = 250.0;  // C: well below what the dome's closure reaches

TEST(ThermalGui, DomeWithTheThermalStage)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(sourceDir() / "resources" / "samples" / "dome.stl")));
  ui::ThermalPanel* thermal = w.thermalPanel();
  ASSERT_NE(thermal, nullptr);
  EXPECT_FALSE(thermal->hasResult());

  // 1. The Thermal tab of the Plan dock: switching the stage on is one undo step.
  ui::PlanPanel* plan = w.planPanel();
  ui::ParamPanel* section = plan->panel("thermal");
  ASSERT_NE(section, nullptr);
  EXPECT_EQ(plan->tabs()->tabText(plan->tabs()->count() - 1), "Thermal");
  auto* enabled = qobject_cast<QCheckBox*>(section->field("enabled")->editor());
  ASSERT_NE(enabled, nullptr);
  EXPECT_FALSE(enabled->isChecked());
  const size_t steps = doc.undoStack().count();
  enabled->click();
  EXPECT_EQ(doc.undoStack().count(), steps + 1);
  EXPECT_EQ(doc.settings()->section("thermal").values().at("enabled"), ParamValue(true));
  auto* limit = qobject_cast<QDoubleSpinBox*>(section->field("interpass_max")->editor());
  ASSERT_NE(limit, nullptr);
  EXPECT_TRUE(limit->suffix().contains("°C")) << limit->suffix().toStdString();
  limit->setValue(kLimit);
  EXPECT_EQ(doc.settings()->section("thermal").getDouble("interpass_max"), kLimit);
  // The limit is drawn and counted; re-planning the dome to it is the pipeline tests' business.
  auto* replan = qobject_cast<QCheckBox*>(section->field("remedy_heat")->editor());
  ASSERT_NE(replan, nullptr);
  replan->setChecked(false);
  EXPECT_FALSE(doc.settings()->section("thermal").getBool("remedy_heat"));
  plan->tabs()->setCurrentIndex(plan->tabs()->count() - 1);
  // Scrolled down to the limit and its remedies, what the picture is about.
  for (QWidget* p = section; p; p = p->parentWidget())
    if (auto* area = qobject_cast<QScrollArea*>(p)) {
      area->ensureWidgetVisible(section->field("remedy_heat"));
      break;
    }
  saveDocScreenshot(w.captureImage(), "thermal-settings.png");

  // 2. Plan: the thermal stage runs in the background plan between process and kinematics.
  ASSERT_TRUE(planAndWait(w));
  const Results& r = doc.results();
  ASSERT_TRUE(r.thermal && r.reports.thermal) << w.lastErrorMessage().toStdString();
  const ThermalStageResult& t = *r.thermal;
  const ThermalStageReport& rep = *r.reports.thermal;
  ASSERT_EQ(t.pointCount(), r.process->size());
  EXPECT_EQ(rep.interpassLimit, kLimit);
  EXPECT_GT(rep.maxInterpass, kLimit);
  EXPECT_GT(rep.pointsOverLimit, 0);
  EXPECT_GE(t.frames.size(), 150u);
  std::cout << "[ measure  ] dome thermal: " << rep.nodes << " nodes, " << rep.steps << " steps, "
            << rep.simulatedTime << " s simulated in " << rep.timings.at("simulation") << " s, max interpass "
            << rep.maxInterpass << " C, " << rep.riskPoints << " risk points\n";
  EXPECT_TRUE(thermal->isVisible());
  EXPECT_TRUE(thermal->hasResult());
  EXPECT_TRUE(thermal->summaryLabel()->text().contains("°C"));
  EXPECT_TRUE(thermal->summaryLabel()->text().contains(QStringLiteral("%1 °C limit").arg(kLimit)));
  EXPECT_TRUE(plan->verdictLabel()->text().contains(
      QStringLiteral("Thermal: interpass up to %1 °C").arg(QLocale().toString(rep.maxInterpass, 'f', 0))))
      << plan->verdictLabel()->text().toStdString();
  // Nothing selected yet: the chart shows the point with the hottest interpass temperature.
  ASSERT_GE(thermal->probeChart()->point(), 0);
  EXPECT_EQ(t.interpass[static_cast<size_t>(thermal->probeChart()->point())], rep.maxInterpass);

  // 3. The spiral coloured by interpass temperature, the limit inside the scale and in the legend.
  ui::SpiralLayer& spiral = w.sceneView()->spiralLayer();
  ASSERT_TRUE(spiral.hasThermal());
  QComboBox* channels = w.displayPanel()->channelCombo();
  const auto chooseChannel = [&](ui::SpiralChannel c) {
    const int index = channels->findData(static_cast<int>(c));
    if (index < 0) return false;
    channels->setCurrentIndex(index);
    return spiral.channel() == c;
  };
  w.displayPanel()->raise();
  ASSERT_TRUE(chooseChannel(ui::SpiralChannel::InterpassTemperature));
  EXPECT_TRUE(spiral.legend().title().contains("Interpass temperature (°C)"));
  EXPECT_TRUE(spiral.legend().title().contains(QStringLiteral("limit %1 °C").arg(kLimit)));
  EXPECT_GE(spiral.channelRange().second, kLimit);
  w.sceneView()->render();
  const QImage interpassShot = w.captureImage();
  EXPECT_GT(distinctColours(interpassShot, sceneRect(w)), 200);
  saveDocScreenshot(interpassShot, "thermal-interpass.png");
  ASSERT_TRUE(chooseChannel(ui::SpiralChannel::PeakTemperature));
  EXPECT_TRUE(spiral.legend().title().contains("melts at"));
  EXPECT_LT(spiral.channelRange().second, rep.maxPeak);  // a few singular peaks off the scale
  ASSERT_TRUE(chooseChannel(ui::SpiralChannel::CollapseRisk));
  EXPECT_EQ(spiral.channelRange(), std::make_pair(0.0, 1.0));

  // 4. Risk zones and the hottest interpass point in the messages panel: a click selects the point
  // and the probe chart draws its temperature with the melting and limit lines.
  QListWidget* list = w.logPanel()->list();
  int zones = 0, overLimit = 0;
  const std::vector<ui::RiskZone> expected = ui::thermalRiskZones(t);
  for (int row = 0; row < list->count(); ++row) {
    const QString text = list->item(row)->text();
    const QVariant v = list->item(row)->data(ui::PathInspector::kPointRole);
    const bool zone = text.contains("Collapse risk, zone"), hot = text.contains("above the 250 °C limit");
    if (!zone && !hot) continue;
    ASSERT_TRUE(v.isValid()) << text.toStdString();
    const auto i = static_cast<size_t>(v.toLongLong());
    ASSERT_LT(i, t.pointCount());
    if (zone) {
      EXPECT_TRUE(t.risk[i]) << i;
      EXPECT_EQ(i, expected[static_cast<size_t>(zones)].worst);
      ++zones;
    } else {
      EXPECT_EQ(t.interpass[i], rep.maxInterpass);
      ++overLimit;
    }
    emit list->itemClicked(list->item(row));
    EXPECT_EQ(w.pointSelection()->index(), static_cast<long long>(i));
    EXPECT_EQ(thermal->probeChart()->point(), static_cast<long long>(i));
  }
  EXPECT_EQ(zones, static_cast<int>(std::min<size_t>(expected.size(), ui::PathInspector::kMaxListedPoints)));
  EXPECT_EQ(rep.riskPoints > 0, zones > 0);
  EXPECT_EQ(overLimit, 1);
  // A point half-way up the dome: laid, peaked, then warmed by every later revolution and cooling.
  ui::ProbeChart* chart = thermal->probeChart();
  const auto middle = static_cast<long long>(t.pointCount() / 2);
  w.pointSelection()->select(middle);
  ASSERT_EQ(chart->point(), middle);
  EXPECT_GT(chart->historyTable()->GetNumberOfRows(), 50);
  EXPECT_EQ(chart->meltingTable()->GetNumberOfRows(), 2);
  EXPECT_EQ(chart->meltingTable()->GetValue(0, 1).ToDouble(), rep.meltingTemperature);
  EXPECT_EQ(chart->limitTable()->GetValue(0, 1).ToDouble(), kLimit);
  ASSERT_EQ(chart->peakTable()->GetNumberOfRows(), 1);
  // The peak under the point source is drawn at the top edge when it is off the scale.
  const double top = chart->chart()->GetAxis(vtkAxis::LEFT)->GetMaximum();
  EXPECT_EQ(chart->peakTable()->GetValue(0, 1).ToDouble(),
            std::min(t.peak[static_cast<size_t>(middle)], top));
  EXPECT_GT(top, rep.meltingTemperature);
  EXPECT_TRUE(chart->title().contains("melting"));
  // Its temperatures are the frames' at the point's node: cooler than its peak, warmer than the air.
  for (vtkIdType k = 0; k < chart->historyTable()->GetNumberOfRows(); ++k) {
    const double v = chart->historyTable()->GetValue(k, 1).ToDouble();
    EXPECT_LE(v, t.peak[static_cast<size_t>(middle)] + t.frames.step) << k;
    EXPECT_GT(v, 19.0) << k;
  }
  w.logPanel()->raise();
  w.sceneView()->render();
  saveDocScreenshot(w.captureImage(), "thermal-risk.png");
  thermal->raise();
  waitFor([] { return false; }, 100);
  saveDocScreenshot(w.captureImage(), "thermal-probe.png");

  // 5. The part by temperature part-way through the build: only what was laid by then is drawn.
  ui::ThermalLayer& field = w.sceneView()->thermalLayer();
  ASSERT_TRUE(field.hasResult());
  thermal->showButton()->click();
  EXPECT_EQ(w.sceneView()->partStyle(), ui::PartStyle::Temperature);
  QComboBox* partStyle = w.displayPanel()->partStyleCombo();
  EXPECT_EQ(partStyle->currentData().toInt(), static_cast<int>(ui::PartStyle::Temperature));
  EXPECT_FALSE(spiral.actor()->GetVisibility());  // it would cover the field
  EXPECT_TRUE(w.displayPanel()->spiralCheck()->isChecked());
  EXPECT_TRUE(field.visible());
  EXPECT_TRUE(field.actor()->GetVisibility());
  const long long all = field.shownTriangles();
  EXPECT_EQ(static_cast<size_t>(all), t.triangles.size());
  QSlider* slider = thermal->frameSlider();
  slider->setValue(slider->maximum() * 2 / 3);
  EXPECT_LT(field.shownTriangles(), all);
  EXPECT_GT(field.shownTriangles(), all / 3);
  EXPECT_TRUE(thermal->timeLabel()->text().startsWith("t = "));
  EXPECT_TRUE(field.legend().title().contains("Temperature (°C)"));
  // Played back: the frames advance on their own and stop at the end.
  const int from = slider->value();
  thermal->play();
  EXPECT_TRUE(thermal->playing());
  EXPECT_TRUE(waitFor([&] { return slider->value() >= from + 2; }, 5000));
  thermal->pause();
  EXPECT_FALSE(thermal->playing());
  // The Simulation dock's time (a path point) moves the frame with it.
  thermal->setTimeOfPoint(static_cast<long long>(t.pointCount() / 4));
  EXPECT_LT(slider->value(), slider->maximum() * 2 / 3);
  slider->setValue(slider->maximum() * 2 / 3);
  w.sceneView()->render();
  const QImage fieldShot = w.captureImage();
  EXPECT_GT(distinctColours(fieldShot, sceneRect(w)), 200);
  saveDocScreenshot(fieldShot, "thermal-field.png");

  // 6. Saved in the project and read back.
  TempDir dir;
  const std::filesystem::path file = dir / "dome_thermal.spira";
  ASSERT_TRUE(w.saveProjectAs(qpath(file)));
  DocumentState plain = doc.state();
  plain.results.thermal.reset();
  plain.results.reports.thermal.reset();
  const auto withBytes = std::filesystem::file_size(file), plainBytes = encodeProject(plain).size();
  std::cout << "[ measure  ] project with thermal results: " << withBytes / 1024 << " KiB, without "
            << plainBytes / 1024 << " KiB\n";
  EXPECT_LT(withBytes - plainBytes, 8u << 20);  // the frames are quantised and stored as laid
  const DocumentState back = loadProject(file);
  ASSERT_TRUE(back.results.thermal && back.results.reports.thermal);
  EXPECT_EQ(*back.results.thermal, t);

  // 7. Cancelled while the thermal stage runs: the previous results stay, thermal ones included.
  doc.setParam("thermal", "cooling", 5.0);  // drops the thermal stage and what follows
  EXPECT_FALSE(doc.results().thermal);
  doc.undo();
  const auto before = doc.results().thermal;
  ASSERT_TRUE(before);
  bool finished = false;
  ui::TaskOutcome outcome;
  const auto c = QObject::connect(&w, &MainWindow::planFinished, [&](const ui::TaskOutcome& o) {
    finished = true;
    outcome = o;
  });
  ui::StageProgress* progress = plan->progress();
  w.actions().plan->trigger();
  const int thermalStage = kThermalPlanStage;
  ASSERT_TRUE(waitFor([&] { return finished || progress->currentStage() >= thermalStage; }, 240000));
  ASSERT_FALSE(finished) << "the plan finished before its thermal stage could be cancelled";
  EXPECT_EQ(progress->currentStage(), thermalStage);
  EXPECT_TRUE(progress->stageShown(thermalStage));
  progress->cancelButton()->click();
  ASSERT_TRUE(waitFor([&] { return finished; }, 10000));
  QObject::disconnect(c);
  EXPECT_EQ(outcome.status, ui::TaskOutcome::Status::Cancelled);
  EXPECT_EQ(doc.results().thermal, before);
  EXPECT_TRUE(thermal->hasResult());
}

// The dwell remedy chosen in the Thermal tab: the plan re-planned with waits before the hot
// revolutions near the closure, and the Plan dock's verdict says what that cost.
TEST(ThermalGui, DwellRemedyAndItsCostInTheVerdict)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(sourceDir() / "resources" / "samples" / "dome.stl")));
  ui::PlanPanel* plan = w.planPanel();
  ui::ParamPanel* section = plan->panel("thermal");
  ASSERT_NE(section, nullptr);
  qobject_cast<QCheckBox*>(section->field("enabled")->editor())->click();
  qobject_cast<QDoubleSpinBox*>(section->field("interpass_max")->editor())->setValue(600.0);
  qobject_cast<QCheckBox*>(section->field("remedy_heat")->editor())->setChecked(false);
  auto* dwell = qobject_cast<QCheckBox*>(section->field("remedy_dwell")->editor());
  ASSERT_NE(dwell, nullptr);
  dwell->setChecked(true);
  EXPECT_TRUE(doc.settings()->section("thermal").getBool("remedy_dwell"));
  // Coarser than the sample's plan, no cooling tail and few frames: each re-planning round simulates
  // the whole build again.
  doc.setParam("decomposer.isovalue", "points_per_rev", 60);
  doc.setParam("thermal", "cooling", 0.0);
  doc.setParam("thermal", "frames", 20);
  ASSERT_TRUE(planAndWait(w, 480000));
  const Results& r = doc.results();
  ASSERT_TRUE(r.thermal && r.reports.thermal) << w.lastErrorMessage().toStdString();
  const ThermalStageReport& rep = *r.reports.thermal;
  ASSERT_TRUE(rep.limitMet.has_value());
  EXPECT_TRUE(*rep.limitMet) << rep.whyNotMet.value_or("");
  EXPECT_LE(rep.maxInterpass, 600.0);
  ASSERT_TRUE(rep.dwells.has_value());
  EXPECT_GT(*rep.dwells, 0);
  const QString verdict = plan->verdictLabel()->text();
  EXPECT_TRUE(verdict.contains("Re-planned (dwell)")) << verdict.toStdString();
  EXPECT_TRUE(verdict.contains(QStringLiteral("%1 dwell").arg(*rep.dwells))) << verdict.toStdString();
  std::cout << "[ measure  ] dome re-planned with dwells: " << *rep.dwells << " dwells, "
            << rep.dwellTime.value_or(0.0) << " s, max interpass " << rep.maxInterpass << " C\n";
  plan->tabs()->setCurrentIndex(plan->tabs()->count() - 1);
  for (QWidget* p = section; p; p = p->parentWidget())
    if (auto* area = qobject_cast<QScrollArea*>(p)) {
      area->ensureWidgetVisible(section->field("max_dwell"));
      break;
    }
  saveDocScreenshot(w.captureImage(), "thermal-dwell.png");
}

}  // namespace
}  // namespace spira::test
