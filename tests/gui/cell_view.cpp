// The robot cell in the 3D view: a bundled cell chosen from the Cell dock appears around the part
// with the camera fitted to the whole cell; editing the part's placement in the cell is one undo
// step and moves the cell around the part; a robot whose mesh is missing still shows, with a
// stand-in and a warning.
#include <array>

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QListWidget>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QString>

#include <gtest/gtest.h>

#include <vtkRenderer.h>
#include "builtin_plugins.h"

#include "spira/base/atomic_file.h"
#include "spira/document/document.h"
#include "spira/document/kinematics_result.h"
#include "spira/robotcell/cell_file.h"
#include "spira/ui/panels/cell_panel.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/simulation_panel.h"
#include "spira/ui/views/cell_workspace.h"
#include "spira/ui/views/path_inspector.h"
#include "spira/ui/views/point_selection.h"
#include "spira/ui/views/robot_layer.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;

bool logContains(MainWindow& w, const QString& text)
{
  for (int i = 0; i < w.logPanel()->count(); ++i)
    if (w.logPanel()->text(i).contains(text)) return true;
  return false;
}

// Whether every corner of `b` projects inside the view.
bool insideView(vtkRenderer* renderer, const std::array<double, 6>& b)
{
  for (int i = 0; i < 8; ++i) {
    renderer->SetWorldPoint(b[i & 1 ? 1 : 0], b[i & 2 ? 3 : 2], b[i & 4 ? 5 : 4], 1.0);
    renderer->WorldToView();
    double v[3];
    renderer->GetViewPoint(v);
    if (std::abs(v[0]) > 1.0 || std::abs(v[1]) > 1.0) return false;
  }
  return true;
}

TEST(CellView, BundledCellAroundThePart)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(sourceDir() / "resources" / "samples" / "dome.stl")));
  const QImage partOnly = w.captureImage();
  ui::CellWorkspace* cells = w.cellWorkspace();
  ui::RobotLayer& robot = cells->robotLayer();
  QComboBox* combo = cells->cellPanel()->cellCombo();
  const QString file = QFileInfo(qpath(sourceDir() / "resources" / "cells" / "fanuc_m20ia_positioner.cell"))
                           .canonicalFilePath();
  const int item = combo->findData(file, Qt::UserRole);
  ASSERT_GE(item, 1);
  EXPECT_TRUE(combo->itemText(item).startsWith("FANUC ARC Mate 120iC"));
  combo->setCurrentIndex(item);
  emit combo->activated(item);  // as a user's choice
  ASSERT_TRUE(doc.cell());
  ASSERT_TRUE(robot.hasCell());
  EXPECT_EQ(combo->currentIndex(), item);
  EXPECT_FALSE(cells->simulationPanel()->hasMotion());  // nothing solved yet
  // The camera shows the whole cell and the part.
  w.sceneView()->render();
  EXPECT_TRUE(insideView(w.sceneView()->renderer(), robot.bounds()));
  const std::array<double, 6> b = robot.bounds();
  EXPECT_GT(b[5] - b[4], 1000.0);  // a robot, not a part: over a metre high
  const QImage shot = w.captureImage();
  EXPECT_GT(distinctColours(shot, sceneRect(w)), 400);
  EXPECT_GT(meanDifference(shot, partOnly, sceneRect(w)), 3.0);
  saveDocScreenshot(shot, "cell-view.png");

  // Editing the part's height on the table is one undo step; the part stays where the scene
  // draws it, so the whole cell moves down under it by the same amount.
  const Transform base = robot.linkTransform(0);
  const size_t steps = doc.undoStack().count();
  QDoubleSpinBox* z = cells->cellPanel()->partOffset(2);
  z->setValue(25.0);
  emit z->editingFinished();
  EXPECT_EQ(doc.undoStack().count(), steps + 1);
  EXPECT_DOUBLE_EQ(doc.cell()->T_mount_part.translation().z(), 25.0);
  EXPECT_NEAR((robot.linkTransform(0).translation() - base.translation()).z(), -25.0, 1e-9);
  doc.undo();
  EXPECT_DOUBLE_EQ(doc.cell()->T_mount_part.translation().z(), 0.0);
  EXPECT_DOUBLE_EQ(z->value(), 0.0);
  EXPECT_LT((robot.linkTransform(0).translation() - base.translation()).norm(), 1e-9);
  // The torch length is a cell edit too.
  QDoubleSpinBox* tcp = cells->cellPanel()->tcpLength();
  EXPECT_DOUBLE_EQ(tcp->value(), 350.0);
  tcp->setValue(400.0);
  emit tcp->editingFinished();
  EXPECT_DOUBLE_EQ(doc.cell()->tool.T_flange_tcp.translation().z(), 400.0);
  doc.undo();
  EXPECT_DOUBLE_EQ(doc.cell()->tool.T_flange_tcp.translation().z(), 350.0);

  // Both cell docks can be closed and brought back from the View menu.
  for (QDockWidget* dock : {cells->cellDock(), cells->simulationDock()}) {
    QAction* toggle = dock->toggleViewAction();
    bool listed = false;
    for (QAction* a : w.menuBar()->actions())
      if (a->menu() && a->text().remove('&') == "View")
        listed = listed || a->menu()->actions().contains(toggle);
    EXPECT_TRUE(listed) << dock->windowTitle().toStdString();
    dock->close();
    EXPECT_FALSE(dock->isVisible());
    toggle->trigger();
    EXPECT_TRUE(dock->isVisible());
  }

  // "No cell" removes it (undoably) and the robot goes.
  emit combo->activated(0);
  EXPECT_FALSE(doc.cell());
  EXPECT_FALSE(robot.hasCell());
  doc.undo();
  EXPECT_TRUE(robot.hasCell());
}

// The ABB cell is offered like the others; the dome planned on it is reached everywhere and drawn with
// the arm over the positioner.
TEST(CellView, TheAbbCellPlansTheDome)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(sourceDir() / "resources" / "samples" / "dome.stl")));
  ui::CellWorkspace* cells = w.cellWorkspace();
  QComboBox* combo = cells->cellPanel()->cellCombo();
  const QString file = QFileInfo(qpath(sourceDir() / "resources" / "cells" / "abb_irb1600_positioner.cell"))
                           .canonicalFilePath();
  const int item = combo->findData(file, Qt::UserRole);
  ASSERT_GE(item, 1);
  EXPECT_TRUE(combo->itemText(item).startsWith("ABB IRB 1600")) << combo->itemText(item).toStdString();
  combo->setCurrentIndex(item);
  emit combo->activated(item);
  ASSERT_TRUE(doc.cell());
  ASSERT_TRUE(cells->robotLayer().hasCell());
  ASSERT_TRUE(planAndWait(w)) << w.lastErrorMessage().toStdString();
  ASSERT_TRUE(doc.results().kinematics);
  EXPECT_TRUE(cells->simulationPanel()->hasMotion());
  // On its riser the arm clears the positioner over the whole dome: nothing is flagged.
  for (int i = 0; i < w.logPanel()->count(); ++i) {
    EXPECT_FALSE(w.logPanel()->text(i).contains("collid")) << w.logPanel()->text(i).toStdString();
    EXPECT_FALSE(w.logPanel()->text(i).contains("out of reach")) << w.logPanel()->text(i).toStdString();
  }
  w.sceneView()->render();
  EXPECT_TRUE(insideView(w.sceneView()->renderer(), cells->robotLayer().bounds()));
  saveDocScreenshot(w.captureImage(), "cell-abb.png");
}

TEST(CellView, MissingMeshShowsAStandInAndAWarning)
{
  TempDir dir;
  const auto robotDir = sourceDir() / "resources" / "robots" / "kuka_kr16_2";
  std::string urdf = readFile((robotDir / "robot.urdf").string());
  urdf = QString::fromStdString(urdf)
             .replace(QStringLiteral("filename=\"meshes/"),
                      QString::fromStdString("filename=\"" + robotDir.string() + "/meshes/"))
             .toStdString();
  const std::string link3 = robotDir.string() + "/meshes/collision/link_3.stl";
  const size_t at = urdf.find(link3);
  ASSERT_NE(at, std::string::npos);
  urdf.replace(at, link3.size(), (dir.path() / "gone" / "link_3.stl").string());
  writeBytes(dir.path() / "robot.urdf", urdf);
  std::string cell = readFile((sourceDir() / "resources" / "cells" / "kuka_kr16_2_table.cell").string());
  cell = QString::fromStdString(cell)
             .replace(QStringLiteral("../robots/kuka_kr16_2/robot.urdf"), QStringLiteral("robot.urdf"))
             .toStdString();
  writeBytes(dir.path() / "broken.cell", cell);

  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(w.cellWorkspace()->cellPanel()->loadCell(qpath(dir.path() / "broken.cell")));
  ui::RobotLayer& robot = w.cellWorkspace()->robotLayer();
  ASSERT_TRUE(robot.hasCell());
  EXPECT_TRUE(logContains(w, "link_3.stl is missing")) << "no warning about the missing mesh";
  bool standIn = false;
  for (size_t l = 0; l < robot.linkCount(); ++l) standIn = standIn || robot.linkName(l) == "link_3";
  EXPECT_TRUE(standIn) << "link_3 should still show (as a stand-in cube)";
  EXPECT_GE(robot.linkCount(), 7u);
}

// A part out of the robot's reach: the plan says how many points, and lists them in the messages
// panel where a click selects the point.
TEST(CellView, PointsOutOfReachAreListedAndSelectable)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  TempDir dir;
  ASSERT_TRUE(openAndWait(w, qpath(writeOpenCylinderStl(dir.path()))));
  CellRecord cell = readCellFile(sourceDir() / "resources" / "cells" / "kuka_kr16_2_table.cell");
  // The KR 16-2 reaches about 1.6 m: 3 m in front of it the part is out of reach everywhere.
  cell.T_mount_part.translation() = Vec3(3000.0, 0.0, 400.0);
  doc.setCell(cell);
  ASSERT_TRUE(planAndWait(w));
  const auto& k = doc.results().kinematics;
  ASSERT_TRUE(k);
  size_t unreachable = 0;
  for (const KinematicsCheck& c : k->checks) unreachable += c.reachable ? 0 : 1;
  EXPECT_EQ(unreachable, k->size());
  auto* list = w.logPanel()->findChild<QListWidget*>();
  ASSERT_NE(list, nullptr);
  int listed = 0;
  bool counted = false;
  for (int row = 0; row < list->count(); ++row) {
    const QString text = list->item(row)->text();
    counted = counted || text.contains(QStringLiteral("%1 more point(s) out of reach")
                                           .arg(QLocale().toString(static_cast<qulonglong>(k->size() - 10))));
    const QVariant v = list->item(row)->data(ui::PathInspector::kPointRole);
    if (!v.isValid() || !text.contains("cannot reach")) continue;
    ++listed;
    const long long i = v.toLongLong();
    ASSERT_LT(static_cast<size_t>(i), k->size());
    EXPECT_FALSE(k->checks[static_cast<size_t>(i)].reachable);
    emit list->itemClicked(list->item(row));
    EXPECT_EQ(w.pointSelection()->index(), i);
  }
  EXPECT_EQ(listed, ui::PathInspector::kMaxListedPoints);
  EXPECT_TRUE(counted);
}

}  // namespace
}  // namespace spira::test
