// Point inspection: the joint chart (axes against the point index with their limits), the shared
// point selection between the process chart, the joint chart and the 3D view (marker, cursor,
// status bar), and the torch frames drawn as glyphs. Truth comes from the data fed in (analytic
// joint curves) and from the planned path itself (positions, abscissae, frames).
#include <cmath>

#include <QAction>
#include <QCheckBox>
#include <QDockWidget>
#include <QLabel>
#include <QLocale>
#include <QTest>

#include <QVTKOpenGLNativeWidget.h>
#include <gtest/gtest.h>

#include <vtkAxis.h>
#include <vtkCamera.h>
#include <vtkChartXY.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkVariant.h>
#include "builtin_plugins.h"

#include "spira/base/units.h"
#include "spira/document/document.h"
#include "spira/document/kinematics_result.h"
#include "spira/path/tool_frame.h"
#include "spira/ui/charts/joint_chart.h"
#include "spira/ui/charts/process_chart.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/views/frame_glyphs.h"
#include "spira/ui/views/path_inspector.h"
#include "spira/ui/views/point_selection.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::JointChart;
using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;
using spira::ui::PathInspector;
using spira::ui::PointSelection;

constexpr size_t kPoints = 240;

// Axis a at point i: a sine of its own phase and amplitude, in controller degrees.
double jointValue(size_t a, size_t i)
{
  return (20.0 + 10.0 * static_cast<double>(a)) *
         std::sin(2.0 * kPi * static_cast<double>(i) / kPoints + 0.5 * a);
}

std::shared_ptr<const KinematicsResult> syntheticKinematics(bool positioner)
{
  JointTrajectory j;
  j.controller = "fanuc_r30ib";
  j.cellName = "synthetic";
  j.hasPositioner = positioner;
  for (size_t a = 0; a < 6; ++a)
    j.robotLimits[a] = {"J" + std::to_string(a + 1), -100.0 - 10.0 * a, 120.0 + 5.0 * a, 200.0};
  j.externalLimits[0] = {"E1", -135.0, 135.0, 90.0};
  j.externalLimits[1] = {"E2", -360.0, 360.0, 90.0};
  Trajectory path;
  for (size_t i = 0; i < kPoints; ++i) {
    JointPoint p;
    for (size_t a = 0; a < 6; ++a) p.robotDeg[a] = jointValue(a, i);
    p.externalDeg = {jointValue(6, i), jointValue(7, i)};
    p.reachable = i != 57;
    p.collision = i == 190;
    j.points.push_back(p);
    TrajectoryPoint t;
    t.position = Vec3(static_cast<double>(i), 0.0, 0.0);
    path.points.push_back(t);
  }
  return std::make_shared<const KinematicsResult>(makeKinematicsResult(std::move(j), std::move(path)));
}

TEST(JointChart, DrawsEveryAxisWithItsLimitsAndFlagsBadPoints)
{
  PointSelection selection;
  JointChart chart(&selection);
  chart.resize(900, 520);
  chart.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&chart, 10000));
  EXPECT_FALSE(chart.hasKinematics());

  chart.setKinematics(syntheticKinematics(false));
  ASSERT_EQ(chart.axisCount(), 6);
  for (int a = 0; a < 6; ++a) {
    vtkTable* t = chart.table(a);
    ASSERT_EQ(t->GetNumberOfRows(), static_cast<vtkIdType>(kPoints));
    for (size_t i : {size_t(0), size_t(33), kPoints - 1}) {
      EXPECT_DOUBLE_EQ(t->GetValue(static_cast<vtkIdType>(i), 0).ToDouble(), static_cast<double>(i));
      EXPECT_DOUBLE_EQ(t->GetValue(static_cast<vtkIdType>(i), 1).ToDouble(),
                       jointValue(static_cast<size_t>(a), i));
    }
    EXPECT_DOUBLE_EQ(chart.limitTable(a, 0)->GetValue(0, 1).ToDouble(), -100.0 - 10.0 * a);
    EXPECT_DOUBLE_EQ(chart.limitTable(a, 1)->GetValue(1, 1).ToDouble(), 120.0 + 5.0 * a);
    EXPECT_DOUBLE_EQ(chart.limitTable(a, 1)->GetValue(1, 0).ToDouble(), static_cast<double>(kPoints - 1));
  }
  // With a positioner, its two axes follow the arm's six.
  chart.setKinematics(syntheticKinematics(true));
  ASSERT_EQ(chart.axisCount(), 8);
  EXPECT_DOUBLE_EQ(chart.table(7)->GetValue(100, 1).ToDouble(), jointValue(7, 100));
  EXPECT_DOUBLE_EQ(chart.limitTable(6, 0)->GetValue(0, 1).ToDouble(), -135.0);
  EXPECT_EQ(chart.chart(6)->GetAxis(vtkAxis::LEFT)->GetTitle(), std::string("E1 (deg)"));
  chart.render();
  QApplication::processEvents();

  // The cursor follows the selection; a click on any axis's chart selects the point under it.
  selection.select(120);
  EXPECT_EQ(chart.cursor(), 120);
  const QPoint at = chart.positionOf(3, 80);
  QTest::mouseClick(chart.vtkWidget(), Qt::LeftButton, Qt::NoModifier, at);
  EXPECT_NEAR(static_cast<double>(selection.index()), 80.0, 1.0);
  EXPECT_EQ(chart.cursor(), selection.index());
  EXPECT_EQ(chart.indexAt(QPoint(-5, -5)), -1);
  const QImage image = chart.grabImage();
  EXPECT_GT(distinctColours(image, image.rect()), 30);
  selection.clear();
  EXPECT_EQ(chart.cursor(), -1);
}

class PlannedCylinder : public testing::Test {
 protected:
  void SetUp() override
  {
    w = std::make_unique<MainWindow>(doc, builtinRegistry(), MainWindowOptions{false, false});
    showAndWait(*w);
    ASSERT_TRUE(openAndWait(*w, qpath(writeOpenCylinderStl(dir.path()))));
    ASSERT_TRUE(planAndWait(*w));
    ASSERT_TRUE(doc.results().process) << w->lastErrorMessage().toStdString();
    inspector = w->pathInspector();
  }

  TempDir dir;
  Document doc;
  std::unique_ptr<MainWindow> w;
  PathInspector* inspector = nullptr;
};

TEST_F(PlannedCylinder, ChartClickSelectsThePointAndMarksItIn3D)
{
  const Trajectory& path = *doc.results().process;
  ASSERT_EQ(inspector->path(), &path);
  ASSERT_EQ(inspector->abscissa().size(), path.size());
  EXPECT_NEAR(inspector->abscissa().back(), path.length(), 1e-9 * path.length());

  w->chartDock()->toggleViewAction()->trigger();
  ASSERT_TRUE(waitFor([&] { return w->chartDock()->isVisible(); }, 5000));
  QApplication::processEvents();
  w->processChart()->render();
  auto* chartWidget = w->processChart()->findChild<QVTKOpenGLNativeWidget*>();
  ASSERT_NE(chartWidget, nullptr);

  const long long target = static_cast<long long>(path.size() * 2 / 3);
  const QPoint at = inspector->chartPositionOf(target);
  QTest::mouseClick(chartWidget, Qt::LeftButton, Qt::NoModifier, at);
  const long long picked = w->pointSelection()->index();
  ASSERT_GE(picked, 0);
  // Within one pixel's worth of abscissa of the point aimed at.
  vtkAxis* x = w->processChart()->chart(ui::ProcessChart::HeightRow)->GetAxis(vtkAxis::BOTTOM);
  const double unit = w->processChart()->abscissaUnit() == "m" ? 1000.0 : 1.0;
  const double perPixel =
      unit * (x->GetMaximum() - x->GetMinimum()) / (x->GetPoint2()[0] - x->GetPoint1()[0]);
  EXPECT_LE(std::abs(inspector->abscissa()[static_cast<size_t>(picked)] -
                     inspector->abscissa()[static_cast<size_t>(target)]),
            1.5 * perPixel);

  // The 3D marker sits on the selected point; the chart cursor at its abscissa; the status bar
  // reads its channels.
  ASSERT_TRUE(inspector->markerVisible());
  const Vec3 expected = doc.part()->T_world_part * path.points[static_cast<size_t>(picked)].position;
  EXPECT_LT((inspector->markerPosition() - expected).norm(), 1e-9);
  ASSERT_TRUE(inspector->chartCursor());
  EXPECT_NEAR(*inspector->chartCursor() * unit, inspector->abscissa()[static_cast<size_t>(picked)], 1e-9);
  const QString status = inspector->statusLabel()->text();
  EXPECT_TRUE(status.startsWith(QStringLiteral("Point %1 of").arg(QLocale().toString(picked))))
      << status.toStdString();
  EXPECT_TRUE(
      status.contains(QStringLiteral("h = %1 mm")
                          .arg(QLocale().toString(path.points[static_cast<size_t>(picked)].height, 'f', 3))));
  EXPECT_TRUE(status.contains("TS = ")) << status.toStdString();

  // A drag pans the chart; it selects nothing.
  w->pointSelection()->clear();
  QTest::mousePress(chartWidget, Qt::LeftButton, Qt::NoModifier, at);
  QTest::mouseMove(chartWidget, at + QPoint(40, 0));
  QTest::mouseRelease(chartWidget, Qt::LeftButton, Qt::NoModifier, at + QPoint(40, 0));
  EXPECT_EQ(w->pointSelection()->index(), -1);
  EXPECT_FALSE(inspector->markerVisible());
  EXPECT_FALSE(inspector->chartCursor());
  EXPECT_TRUE(inspector->statusLabel()->text().isEmpty());
}

TEST_F(PlannedCylinder, ClickOnTheSpiralIn3DSelectsThePointUnderTheCursor)
{
  const Trajectory& path = *doc.results().process;
  ui::SceneView* view = w->sceneView();
  view->render();
  auto* vtkWidget = view->findChild<QVTKOpenGLNativeWidget*>();
  ASSERT_NE(vtkWidget, nullptr);
  // A point on the side of the cylinder facing the camera (nearest to it), half-way up.
  const Vec3 eye(view->renderer()->GetActiveCamera()->GetPosition());
  long long aim = -1;
  double best = HUGE_VAL;
  for (size_t i = path.size() / 3; i < 2 * path.size() / 3; ++i) {
    const double d = (doc.part()->T_world_part * path.points[i].position - eye).norm();
    if (d < best) best = d, aim = static_cast<long long>(i);
  }
  ASSERT_GE(aim, 0);
  const QPoint at = inspector->viewPositionOf(aim);
  ASSERT_TRUE(vtkWidget->rect().contains(at));
  QTest::mouseClick(vtkWidget, Qt::LeftButton, Qt::NoModifier, at);
  const long long picked = w->pointSelection()->index();
  ASSERT_GE(picked, 0);
  // The point picked is under the cursor (the nearest path point to the picked spot on the line:
  // a neighbour of the aimed one at most a few pixels away on screen).
  const QPoint seen = inspector->viewPositionOf(picked);
  EXPECT_LE((seen - at).manhattanLength(), 6) << "aimed " << aim << ", picked " << picked;
  EXPECT_LT(
      (path.points[static_cast<size_t>(picked)].position - path.points[static_cast<size_t>(aim)].position)
          .norm(),
      3.0);
  EXPECT_TRUE(inspector->markerVisible());
  // Nothing under the cursor (a corner of the view): the selection stays.
  QTest::mouseClick(vtkWidget, Qt::LeftButton, Qt::NoModifier, QPoint(3, 3));
  EXPECT_EQ(w->pointSelection()->index(), picked);
}

TEST_F(PlannedCylinder, TorchFramesAreDrawnOnDemandAlongTheToolFrames)
{
  const Trajectory& path = *doc.results().process;
  ui::FrameGlyphs& glyphs = inspector->frameGlyphs();
  EXPECT_FALSE(glyphs.visible());
  w->displayPanel()->framesCheck()->setChecked(true);
  ASSERT_TRUE(glyphs.visible());
  const long long n = static_cast<long long>(path.size());
  EXPECT_EQ(glyphs.stride(),
            std::max<long long>(1, (n + ui::FrameGlyphs::kMaxGlyphs - 1) / ui::FrameGlyphs::kMaxGlyphs));
  EXPECT_EQ(glyphs.glyphCount(), (n + glyphs.stride() - 1) / glyphs.stride());
  EXPECT_LE(glyphs.glyphCount(), ui::FrameGlyphs::kMaxGlyphs);
  vtkPolyData* lines = glyphs.polyData();
  ASSERT_EQ(lines->GetNumberOfLines(), 3 * glyphs.glyphCount());
  // Each triad is the tool frame of its point: x along the travel, z the torch axis (-build).
  for (long long g : {0LL, glyphs.glyphCount() / 2, glyphs.glyphCount() - 1}) {
    const Transform T =
        doc.part()->T_world_part * toolFrame(path.points[static_cast<size_t>(g * glyphs.stride())]);
    double o[3], tip[3];
    lines->GetPoint(4 * g, o);
    EXPECT_LT((Vec3(o[0], o[1], o[2]) - T.translation()).norm(), 1e-4);  // float points
    for (int a = 0; a < 3; ++a) {
      lines->GetPoint(4 * g + 1 + a, tip);
      const Vec3 axis = (Vec3(tip[0], tip[1], tip[2]) - Vec3(o[0], o[1], o[2])) / glyphs.axisLength();
      EXPECT_LT((axis - T.linear().col(a)).norm(), 1e-4) << "glyph " << g << " axis " << a;
    }
  }
  const QImage with = w->captureImage();
  w->displayPanel()->framesCheck()->setChecked(false);
  EXPECT_FALSE(glyphs.visible());
  const QImage without = w->captureImage();
  EXPECT_GT(meanDifference(with, without, sceneRect(*w)), 0.2);
}

}  // namespace
}  // namespace spira::test
