// The whole day's work on the bundled dome, as a process engineer goes through it: import the
// part, choose the FANUC cell with its positioner, plan, colour the spiral by another channel,
// scrub the build, pick a point on the process chart and find it in 3D, read the robot's axes in
// the joint chart, show the torch frames, and export the FANUC program through the dialog, read
// back. Every step asserts on the model and writes a documentation screenshot (docs/screenshots),
// checked rendered and different from the previous one.
#include <fstream>

#include <QAction>
#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSlider>
#include <QTabWidget>
#include <QTest>

#include <QVTKOpenGLNativeWidget.h>
#include <gtest/gtest.h>

#include <vtkCamera.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkVariant.h>
#include "builtin_plugins.h"

#include "spira/base/units.h"
#include "spira/document/document.h"
#include "spira/document/kinematics_result.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
#include "spira/ui/charts/joint_chart.h"
#include "spira/ui/charts/process_chart.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/export_dialog.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/panels/simulation_panel.h"
#include "spira/ui/panels/stage_progress.h"
#include "spira/ui/views/frame_glyphs.h"
#include "spira/ui/views/path_inspector.h"
#include "spira/ui/views/point_selection.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/spiral_layer.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;
using spira::ui::SpiralChannel;

QImage shoot(MainWindow& w, const QString& name, const QImage* previous)
{
  const QImage image = w.captureImage();
  EXPECT_GT(distinctColours(image, sceneRect(w)), 400) << name.toStdString() << " looks blank";
  if (previous) {
    EXPECT_GT(meanDifference(image, *previous, image.rect()), 0.5) << name.toStdString();
  }
  saveDocScreenshot(image, name);
  return image;
}

// The first target after which the arc starts, from a FANUC .ls: XYZ (mm) and the GP2 axes (deg).
struct TpTarget {
  Vec3 xyz;
  double e1 = 0.0, e2 = 0.0;
};

TpTarget arcStartTarget(const std::string& text)
{
  TpTarget t;
  const QString all = QString::fromStdString(text);
  // The instruction, not the header comment naming it.
  const QRegularExpressionMatch start =
      QRegularExpression(QStringLiteral(R"(\d+:\s+Arc Start\[)")).match(all);
  EXPECT_TRUE(start.hasMatch());
  const int arc = start.hasMatch() ? start.capturedStart(0) : 0;
  QString last;
  QRegularExpressionMatchIterator moves =
      QRegularExpression(QStringLiteral(R"(L P\[(\d+)\])")).globalMatch(all.left(arc));
  while (moves.hasNext()) last = moves.next().captured(1);
  const QRegularExpressionMatch m =
      QRegularExpression(
          QStringLiteral("P\\[") + last +
          QStringLiteral(
              R"(\]\{[\s\S]*?X =\s*(-?[\d.]+)\s*mm,\s*Y =\s*(-?[\d.]+)\s*mm,\s*Z =\s*(-?[\d.]+)\s*mm[\s\S]*?GP2:[\s\S]*?J1=\s*(-?[\d.]+)\s*deg,\s*J2=\s*(-?[\d.]+)\s*deg)"))
          .match(all);
  EXPECT_TRUE(m.hasMatch()) << "no P[" << last.toStdString() << "] with GP2 axes";
  if (!m.hasMatch()) return t;
  const auto num = [&](int k) { return m.captured(k).toDouble(); };
  t.xyz = Vec3(num(1), num(2), num(3));
  t.e1 = num(4);
  t.e2 = num(5);
  return t;
}

TEST(Workflow, DomeWithFanucCellFromImportToExport)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ui::SceneView* view = w.sceneView();
  ui::DisplayPanel* display = w.displayPanel();

  // 1. Import the dome; 2. choose the FANUC cell with its tilt-rotate positioner.
  ASSERT_TRUE(openAndWait(w, qpath(sourceDir() / "resources" / "samples" / "dome.stl")));
  const std::filesystem::path cellFile = sourceDir() / "resources" / "cells" / "fanuc_m20ia_positioner.cell";
  doc.setCell(readCellFile(cellFile));
  ASSERT_TRUE(doc.cell());
  ASSERT_TRUE(doc.cell()->hasPositioner());

  // 3. Plan.
  ASSERT_TRUE(planAndWait(w));
  ASSERT_TRUE(doc.results().process) << w.lastErrorMessage().toStdString();
  // Planning again shows the stage bars without growing the window: a resize relays out and
  // repaints the whole window, 80 ms on software OpenGL.
  const QSize size = w.size();
  QSignalSpy again(&w, &MainWindow::planFinished);
  w.actions().plan->trigger();
  EXPECT_TRUE(w.planPanel()->progress()->isVisible());
  QTest::qWait(50);
  EXPECT_EQ(w.size(), size);
  ASSERT_TRUE(waitFor([&] { return again.count() > 0; }, 120000));
  EXPECT_EQ(w.size(), size);
  const Trajectory& path = *doc.results().process;
  const QImage planned = shoot(w, "workflow-planned.png", nullptr);

  // 4. Colour by travel speed, then back to the deposit height.
  ASSERT_TRUE(display->setChannel(SpiralChannel::TravelSpeed));
  EXPECT_STREQ(view->spiralLayer().mapper()->GetArrayName(), "travel_speed");
  const QImage speed = shoot(w, "workflow-travel-speed.png", &planned);
  ASSERT_TRUE(display->setChannel(SpiralChannel::Height));
  EXPECT_STREQ(view->spiralLayer().mapper()->GetArrayName(), "height");

  // 5. The build up to the middle revolution.
  const int middle = view->spiralLayer().revolutionCount() / 2;
  display->revolutionSlider()->setValue(middle);
  EXPECT_EQ(view->spiralLayer().shownPointCount(),
            std::count_if(path.points.begin(), path.points.end(),
                          [&](const TrajectoryPoint& p) { return p.revolution <= middle; }));
  display->revolutionSlider()->setValue(display->revolutionSlider()->maximum());
  EXPECT_EQ(view->spiralLayer().shownPointCount(), static_cast<long long>(path.size()));

  // 6. A point picked on the process chart is marked in the 3D view and read in the status bar.
  w.chartDock()->toggleViewAction()->trigger();
  ASSERT_TRUE(waitFor([&] { return w.chartDock()->isVisible(); }, 5000));
  waitFor([] { return false; }, 300);
  w.processChart()->render();
  ui::PathInspector* inspector = w.pathInspector();
  auto* chartWidget = w.processChart()->findChild<QVTKOpenGLNativeWidget*>();
  ASSERT_NE(chartWidget, nullptr);
  // A point of the middle of the build on the side facing the camera (nearest to it).
  w.actions().fitView->trigger();
  view->render();
  const Vec3 eye(view->renderer()->GetActiveCamera()->GetPosition());
  long long aim = -1;
  double nearest = HUGE_VAL;
  for (size_t i = path.size() / 2; i < path.size() * 3 / 5; ++i) {
    const double d = (doc.part()->T_world_part * path.points[i].position - eye).norm();
    if (d < nearest) nearest = d, aim = static_cast<long long>(i);
  }
  QTest::mouseClick(chartWidget, Qt::LeftButton, Qt::NoModifier, inspector->chartPositionOf(aim));
  const long long picked = w.pointSelection()->index();
  ASSERT_GE(picked, 0);
  EXPECT_LT(std::abs(inspector->abscissa()[static_cast<size_t>(picked)] -
                     inspector->abscissa()[static_cast<size_t>(aim)]),
            0.01 * path.length());
  ASSERT_TRUE(inspector->markerVisible());
  EXPECT_LT((inspector->markerPosition() -
             doc.part()->T_world_part * path.points[static_cast<size_t>(picked)].position)
                .norm(),
            1e-9);
  EXPECT_TRUE(inspector->statusLabel()->text().startsWith("Point "));
  // Framed on the part: the cell around it is ten times larger.
  w.actions().fitView->trigger();
  const QImage selected = shoot(w, "point-selection.png", &speed);

  // 7. The joint chart: the arm's six axes and the positioner's two against the point index.
  // The plan's kinematics stage solved the motion on the cell.
  ASSERT_TRUE(doc.results().kinematics);
  const KinematicsResult& kin = *doc.results().kinematics;
  w.jointDock()->toggleViewAction()->trigger();
  ASSERT_TRUE(waitFor([&] { return w.jointDock()->isVisible(); }, 5000));
  waitFor([] { return false; }, 300);
  ui::JointChart* joints = w.jointChart();
  ASSERT_TRUE(joints->hasKinematics());
  ASSERT_EQ(joints->axisCount(), 8);
  for (int a = 0; a < 8; ++a) {
    EXPECT_EQ(joints->table(a)->GetNumberOfRows(), static_cast<vtkIdType>(kin.size()));
    EXPECT_DOUBLE_EQ(joints->table(a)->GetValue(static_cast<vtkIdType>(kin.size() / 2), 1).ToDouble(),
                     axisValuesDeg(kin, kin.size() / 2)[static_cast<size_t>(a)]);
    EXPECT_DOUBLE_EQ(joints->limitTable(a, 0)->GetValue(0, 1).ToDouble(),
                     kin.axes[static_cast<size_t>(a)].minDeg);
    EXPECT_DOUBLE_EQ(joints->limitTable(a, 1)->GetValue(0, 1).ToDouble(),
                     kin.axes[static_cast<size_t>(a)].maxDeg);
  }
  EXPECT_EQ(joints->cursor(), picked) << "the joint chart shows the point selected on the process chart";
  const QImage jointShot = shoot(w, "joint-chart.png", &selected);
  // A click on the joint chart selects there; the marker follows.
  const long long second = static_cast<long long>(kin.size() / 4);
  QTest::mouseClick(joints->vtkWidget(), Qt::LeftButton, Qt::NoModifier, joints->positionOf(0, second));
  EXPECT_NEAR(static_cast<double>(w.pointSelection()->index()), static_cast<double>(second),
              0.01 * kin.size() + 1.0);
  EXPECT_LT(
      (inspector->markerPosition() -
       doc.part()->T_world_part * path.points[static_cast<size_t>(w.pointSelection()->index())].position)
          .norm(),
      1e-9);

  // Three simulation steps: the robot and positioner move to the next points of the motion.
  auto* sim = w.findChild<ui::SimulationPanel*>();
  ASSERT_NE(sim, nullptr);
  ASSERT_TRUE(sim->hasMotion());
  const size_t start = sim->index();
  for (int k = 0; k < 3; ++k) sim->stepForward();
  EXPECT_EQ(sim->index(), start + 3);
  EXPECT_TRUE(sim->statusText().startsWith(QStringLiteral("Point %1 of").arg(start + 4)))
      << sim->statusText().toStdString();

  // 8. The torch frames along the path.
  const QImage withoutFrames = w.captureImage();
  display->framesCheck()->setChecked(true);
  EXPECT_GT(inspector->frameGlyphs().glyphCount(), 100);
  const QImage frames = shoot(w, "torch-frames.png", &jointShot);
  EXPECT_GT(meanDifference(frames, withoutFrames, sceneRect(w)), 0.3);
  display->framesCheck()->setChecked(false);

  // 9. Export the FANUC program through the dialog; warnings before writing, then read back.
  w.actions().exportProgram->trigger();
  ui::ExportDialog* d = w.exportDialog();
  ASSERT_TRUE(waitFor([&] { return d->isVisible(); }, 5000));
  d->setExporter("export.fanuc_tp");
  waitFor([] { return false; }, 50);
  ASSERT_TRUE(waitFor([&] { return !d->previewBusy(); }, 120000));
  ASSERT_TRUE(d->previewOk()) << d->summaryLabel()->text().toStdString();
  const QString ls = static_cast<QPlainTextEdit*>(d->previewTabs()->widget(0))->toPlainText();
  EXPECT_TRUE(ls.contains("DEFAULT_GROUP\t= 1,1,*,*,*;")) << "the positioner is group 2";
  const std::filesystem::path out = dir / "program";
  std::filesystem::create_directories(out);
  d->setOutputFolder(qpath(out));
  QApplication::processEvents();
  const QImage dialogShot = d->grab().toImage();
  EXPECT_GT(distinctColours(dialogShot, dialogShot.rect()), 50);
  saveDocScreenshot(dialogShot, "export-dialog.png");
  if (!d->warnings().isEmpty()) d->setExporterValue("force", true);  // the user read them and forces
  QSignalSpy written(d, &ui::ExportDialog::exported);
  d->exportButton()->click();
  ASSERT_TRUE(waitFor([&] { return !written.isEmpty(); }, 120000));
  ASSERT_TRUE(written.first().at(0).toBool()) << d->summaryLabel()->text().toStdString();
  const QStringList files = written.first().at(1).toStringList();
  ASSERT_FALSE(files.isEmpty());
  // The document's export stage lists what was written; a change of the export settings drops it.
  ASSERT_TRUE(doc.results().exported);
  EXPECT_EQ(doc.results().exported->exporter, "export.fanuc_tp");
  ASSERT_EQ(doc.results().exported->files.size(), static_cast<size_t>(files.size()));
  EXPECT_EQ(QDir::toNativeSeparators(QString::fromStdString(doc.results().exported->files.front())),
            files.front());
  std::ifstream in(files.front().toStdString(), std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const TpTarget t = arcStartTarget(text);
  // The arc starts on the first planned point, carried by the positioner at the exported axes:
  // p_base = T_base_positioner * forward(E) * T_table_part * p_part (URDF axes from the
  // controller's through the cell's sign and offset).
  const RobotCell cell(*doc.cell());
  ASSERT_NE(cell.positioner(), nullptr);
  const auto& axes = doc.cell()->positionerAxes;
  ASSERT_EQ(axes.size(), 2u);
  const Eigen::Vector2d e(axes[0].sign * (t.e1 + axes[0].offsetDeg) * kPi / 180.0,
                          axes[1].sign * (t.e2 + axes[1].offsetDeg) * kPi / 180.0);
  const Vec3 expected = cell.basePositioner() * cell.positioner()->forward(e) * doc.cell()->T_mount_part *
                        path.points.front().position;
  EXPECT_LT((t.xyz - expected).norm(), 0.05)
      << "exported " << t.xyz.transpose() << ", expected " << expected.transpose();
  d->close();
  const QImage done = w.captureImage();
  EXPECT_GT(meanDifference(done, frames, sceneRect(w)), 0.0);
}

}  // namespace
}  // namespace spira::test
