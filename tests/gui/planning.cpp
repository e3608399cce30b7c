// The planning workflow on the bundled dome, as a user goes through it: open the part, plan,
// look at the field, the generatrices and the spiral by channel, scrub the build revolution by
// revolution, open the process chart. Every step checks the model and the view and writes a
// documentation screenshot (docs/screenshots), checked rendered and different from the last.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSlider>

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkTable.h>
#include <nlohmann/json.hpp>
#include "builtin_plugins.h"

#include "spira/base/units.h"
#include "spira/document/document.h"
#include "spira/ui/charts/process_chart.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/panels/stage_progress.h"
#include "spira/ui/views/field_layer.h"
#include "spira/ui/views/path_layers.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/spiral_layer.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;
using spira::ui::PartStyle;
using spira::ui::ProcessChart;
using spira::ui::SpiralChannel;

constexpr double kDomeRadius = 60.0;  // resources/samples/dome.stl: a hemisphere on z = 0

bool logContains(MainWindow& w, const QString& text)
{
  for (int i = 0; i < w.logPanel()->count(); ++i)
    if (w.logPanel()->text(i).contains(text)) return true;
  return false;
}

// A screenshot that shows something: many colours in the 3D view.
QImage shoot(MainWindow& w, const QString& name)
{
  const QImage image = w.captureImage();
  EXPECT_EQ(image.size(), QSize(1280, 800));
  EXPECT_GT(distinctColours(image, sceneRect(w)), 400) << name.toStdString() << " looks blank";
  saveDocScreenshot(image, name);
  return image;
}

std::pair<double, double> channelRange(const Trajectory& t, double (*get)(const TrajectoryPoint&))
{
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const TrajectoryPoint& p : t.points) lo = std::min(lo, get(p)), hi = std::max(hi, get(p));
  return {lo, hi};
}

TEST(PlanningWorkflow, DomeFromImportToProcessChart)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ui::SceneView* view = w.sceneView();
  ui::DisplayPanel* display = w.displayPanel();

  // 1. Open the sample dome.
  ASSERT_TRUE(openAndWait(w, qpath(sourceDir() / "resources" / "samples" / "dome.stl")));
  ASSERT_TRUE(doc.part());
  const size_t vertices = doc.part()->mesh->vertexCount();
  EXPECT_TRUE(w.planPanel()->verdictLabel()->text().contains("No plan yet"));
  EXPECT_TRUE(w.actions().plan->isEnabled());
  const QImage opened = shoot(w, "main-window.png");

  // 2. Plan: the staged results land in the document, the verdict and the log say how it went.
  const size_t undoSteps = doc.undoStack().count();
  ASSERT_TRUE(planAndWait(w));
  const Results& r = doc.results();
  ASSERT_TRUE(r.field && r.generatrices && r.spiral && r.process) << w.lastErrorMessage().toStdString();
  EXPECT_EQ(r.field->kind, "geodesic_distance");
  EXPECT_EQ(r.field->values.size(), vertices);
  ASSERT_TRUE(r.generatrices->hasClosurePoint);
  EXPECT_EQ(r.spiral->size(), r.process->size());
  ASSERT_TRUE(r.reports.spiral);
  const SpiralStageReport& report = *r.reports.spiral;
  EXPECT_TRUE(report.feasible);
  EXPECT_DOUBLE_EQ(report.hMin, 1.8);  // h = 2 mm, window +/-10 %
  EXPECT_DOUBLE_EQ(report.hMax, 2.2);
  EXPECT_TRUE(logContains(w, "Planned in"));
  EXPECT_TRUE(w.planPanel()->verdictLabel()->text().contains("Feasible plan"));
  EXPECT_FALSE(w.planPanel()->progress()->isVisible());
  EXPECT_FALSE(w.planPanel()->progress()->running());
  EXPECT_FALSE(w.planPanel()->progress()->cancelButton()->isEnabled());
  EXPECT_EQ(doc.undoStack().count(), undoSteps);  // results are not undo steps

  // The view shows every point of the spiral, coloured by deposit height over a faint part.
  ui::SpiralLayer& spiral = view->spiralLayer();
  EXPECT_EQ(view->partStyle(), PartStyle::Transparent);
  EXPECT_EQ(spiral.shownPointCount(), static_cast<long long>(r.process->size()));
  EXPECT_EQ(spiral.violationCount(), 0);
  EXPECT_STREQ(spiral.mapper()->GetArrayName(), "height");
  EXPECT_TRUE(spiral.legend().title().startsWith("Deposit height (mm)\n"))
      << spiral.legend().title().toStdString();
  EXPECT_TRUE(spiral.legend().visible());
  // The window, with the planner's tolerance (0.5 % of h), is the colour scale.
  const double tolerance = report.heightTolerance;
  EXPECT_NEAR(tolerance, 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(spiral.channelRange().first, 1.8 - tolerance);
  EXPECT_DOUBLE_EQ(spiral.channelRange().second, 2.2 + tolerance);
  // The closure point of a hemisphere is its pole.
  ASSERT_TRUE(view->pathLayers().closurePoint());
  const Vec3 pole = *view->pathLayers().closurePoint();
  EXPECT_NEAR(pole.z(), kDomeRadius, 0.5);
  EXPECT_NEAR(std::hypot(pole.x(), pole.y()), 0.0, 1.0);
  w.displayPanel()->raise();
  const QImage planned = shoot(w, "plan-spiral.png");
  EXPECT_GT(meanDifference(planned, opened, sceneRect(w)), 3.0);

  // 3. The part coloured by the geodesic distance from the base: 0 at the base, a quarter
  // meridian (pi r / 2) at the pole; iso-lines every round distance.
  display->setPartStyle(PartStyle::Field);
  display->spiralCheck()->setChecked(false);
  ui::FieldLayer& field = view->fieldLayer();
  ASSERT_TRUE(field.visible());
  EXPECT_NEAR(field.dataRange().first, 0.0, 1e-6);
  EXPECT_NEAR(field.dataRange().second, kPi * kDomeRadius / 2.0, 0.02 * kPi * kDomeRadius / 2.0);
  EXPECT_GT(field.isoSpacing(), 0.0);
  EXPECT_GT(field.isoLines()->GetNumberOfCells(), 100);
  // Iso-lines of the distance are horizontal circles on a hemisphere: every point of one level d
  // sits at the height r sin(d / r), d a multiple of the spacing (heat-method error aside).
  {
    vtkPolyData* iso = field.isoLines();
    const double spacing = field.isoSpacing();
    int onLevel = 0;
    for (vtkIdType i = 0; i < iso->GetNumberOfPoints(); ++i) {
      const double z = std::clamp(iso->GetPoint(i)[2] / kDomeRadius, -1.0, 1.0);
      const double d = kDomeRadius * std::asin(z) / spacing;
      onLevel += std::abs(d - std::round(d)) < 0.15 ? 1 : 0;
    }
    EXPECT_GT(onLevel, 0.95 * static_cast<double>(iso->GetNumberOfPoints()));
  }
  const QString fieldTitle = field.legend().title();
  EXPECT_TRUE(fieldTitle.startsWith("Geodesic distance (mm)")) << fieldTitle.toStdString();
  EXPECT_FALSE(spiral.actor()->GetVisibility());
  const QImage fieldShot = shoot(w, "plan-field.png");
  EXPECT_GT(meanDifference(fieldShot, planned, sceneRect(w)), 3.0);

  // A narrower colour range: the legend follows, the data do not change.
  display->setFieldRange(20.0, 60.0);
  EXPECT_DOUBLE_EQ(field.range().first, 20.0);
  EXPECT_DOUBLE_EQ(field.range().second, 60.0);
  EXPECT_DOUBLE_EQ(display->fieldMin()->value(), 20.0);
  display->setFieldRange(field.dataRange().first, field.dataRange().second);

  // 4. The generatrices over the plain part.
  display->setPartStyle(PartStyle::Shaded);
  display->setGeneratricesVisible(true);
  const int stride = view->pathLayers().stride();
  const long long lineCount = static_cast<long long>(r.generatrices->lines.size());
  EXPECT_LE((lineCount + stride - 1) / stride, ui::PathLayers::kMaxLines);
  EXPECT_EQ(view->pathLayers().lineCount(), (lineCount + stride - 1) / stride);
  const QImage lines = shoot(w, "plan-generatrices.png");
  EXPECT_GT(meanDifference(lines, fieldShot, sceneRect(w)), 3.0);
  display->setGeneratricesVisible(false);

  // 5. The spiral by travel speed, then wire feed and revolution; timing the switch.
  display->setPartStyle(PartStyle::Transparent);
  display->spiralCheck()->setChecked(true);
  view->render();
  double slowest = 0.0, total = 0.0, renderTotal = 0.0;
  const SpiralChannel order[] = {SpiralChannel::TravelSpeed, SpiralChannel::WireFeed,
                                 SpiralChannel::Revolution, SpiralChannel::Height,
                                 SpiralChannel::TravelSpeed};
  for (SpiralChannel c : order) {
    const auto t0 = std::chrono::steady_clock::now();
    ASSERT_TRUE(display->setChannel(c));
    const auto t1 = std::chrono::steady_clock::now();
    view->render();
    const auto t2 = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(t2 - t0).count();
    slowest = std::max(slowest, ms), total += ms;
    renderTotal += std::chrono::duration<double, std::milli>(t2 - t1).count();
  }
  std::cout << "[ measure  ] colouring channel switch on " << r.process->size() << " points: mean "
            << total / std::size(order) << " ms (of which rendering the frame "
            << renderTotal / std::size(order) << " ms), slowest " << slowest << " ms\n";
  RecordProperty("channel_switch_ms_max", static_cast<int>(std::ceil(slowest)));
  EXPECT_STREQ(spiral.mapper()->GetArrayName(), "travel_speed");
  EXPECT_EQ(display->channelCombo()->currentText(), "Travel speed (mm/s)");
  EXPECT_EQ(spiral.legend().title(), "Travel speed (mm/s)");
  const auto ts = channelRange(*r.process, [](const TrajectoryPoint& p) { return p.travelSpeed; });
  EXPECT_DOUBLE_EQ(spiral.channelRange().first, ts.first);
  EXPECT_DOUBLE_EQ(spiral.channelRange().second, ts.second);
  const QImage speed = shoot(w, "spiral-travel-speed.png");
  EXPECT_GT(meanDifference(speed, planned, sceneRect(w)), 1.0);
  // Synergic mode holds the wire feed: 2.3 m/min on every point.
  display->setChannel(SpiralChannel::WireFeed);
  EXPECT_EQ(spiral.legend().title(), "Wire-feed speed (m/min)");
  EXPECT_LT(spiral.channelRange().first, 2.3);
  EXPECT_GT(spiral.channelRange().second, 2.3);

  // 6. The build up to the middle revolution, as a tube.
  display->setChannel(SpiralChannel::Height);
  const int middle = spiral.revolutionCount() / 2;
  ASSERT_GT(middle, 2);
  display->revolutionSlider()->setValue(middle);
  const long long expected = std::count_if(r.process->points.begin(), r.process->points.end(),
                                           [&](const TrajectoryPoint& p) { return p.revolution <= middle; });
  EXPECT_EQ(spiral.shownPointCount(), expected);
  // The dome's spiral ends on its pole, numbered as one more revolution of a single point.
  ASSERT_TRUE(spiral.endsOnAPoint());
  const int rings = spiral.revolutionCount() - 1;
  EXPECT_EQ(rings, report.revolutions - report.collapsedRevolutions);
  EXPECT_TRUE(display->revolutionLabel()->text().startsWith(
      QStringLiteral("Revolution %1 of %2: %3 points").arg(middle + 1).arg(rings).arg(expected)))
      << display->revolutionLabel()->text().toStdString();
  display->setTube(true);
  view->render();
  vtkPolyData* tube = vtkPolyData::SafeDownCast(spiral.mapper()->GetInput());
  ASSERT_NE(tube, nullptr);
  EXPECT_GT(tube->GetNumberOfPolys() + tube->GetNumberOfStrips(), 0);  // a surface, not the polyline
  const QImage half = shoot(w, "spiral-build-up.png");
  EXPECT_GT(meanDifference(half, planned, sceneRect(w)), 1.0);

  // 7. The process chart: three channels against the abscissa, the window's lines, the cut.
  w.chartDock()->toggleViewAction()->trigger();
  ASSERT_TRUE(waitFor([&] { return w.chartDock()->isVisible(); }, 5000));
  ProcessChart* chart = w.processChart();
  const vtkIdType n = static_cast<vtkIdType>(r.process->size());
  for (ProcessChart::Row row :
       {ProcessChart::HeightRow, ProcessChart::TravelSpeedRow, ProcessChart::WireFeedRow})
    EXPECT_EQ(chart->table(row)->GetNumberOfRows(), n);
  const double unit = chart->abscissaUnit() == "m" ? 1000.0 : 1.0;
  EXPECT_NEAR(chart->table(ProcessChart::HeightRow)->GetValue(n - 1, 0).ToDouble() * unit,
              r.process->length(), 1e-6 * r.process->length());
  EXPECT_DOUBLE_EQ(chart->windowTable(0)->GetValue(0, 1).ToDouble(), 1.8);
  EXPECT_DOUBLE_EQ(chart->windowTable(1)->GetValue(1, 1).ToDouble(), 2.2);
  const QImage charted = shoot(w, "process-chart.png");
  const QRect chartRect = rectIn(w, chart);
  EXPECT_GT(chartRect.height(), 200);
  EXPECT_GT(distinctColours(charted, chartRect), 50);
  EXPECT_GT(meanDifference(charted, half, chartRect), 5.0);

  // Back to the whole build: undoing nothing, the results stay as planned.
  display->revolutionSlider()->setValue(display->revolutionSlider()->maximum());
  EXPECT_EQ(spiral.shownPointCount(), static_cast<long long>(r.process->size()));
  EXPECT_TRUE(display->revolutionLabel()->text().startsWith(
      QStringLiteral("All %1 revolutions and the closure point").arg(rings)));
}

// A thin-walled CAD solid (the corpus's straight tube, a 2.45 mm wall, median, from 1.25 to 3.15 mm)
// is planned on its mid-surface, and the verdict says so: the spiral runs inside the drawn solid.
TEST(PlanningWorkflow, ThinWalledSolidVerdictSaysItIsPlannedOnItsMidSurface)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(sourceDir() / "tests" / "data" / "real" / "tube_straight_solid.stl")));
  ASSERT_TRUE(planAndWait(w));
  ASSERT_TRUE(doc.results().spiral) << w.lastErrorMessage().toStdString();
  const QString verdict = w.planPanel()->verdictLabel()->text();
  EXPECT_TRUE(verdict.contains("Thin-walled solid, wall 2.45")) << verdict.toStdString();
  EXPECT_TRUE(verdict.contains("planned on its mid-surface")) << verdict.toStdString();
}

}  // namespace
}  // namespace spira::test
