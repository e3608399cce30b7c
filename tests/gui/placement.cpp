// Placing the part on the substrate from the Placement dock: move, rotate, drop, choose the base
// loop; every edit one undo step, the view following, and the plan following the part.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTest>

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include "builtin_plugins.h"

#include "spira/document/document.h"
#include "spira/document/kinematics_result.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/robotcell/cell_file.h"
#include "spira/ui/panels/placement_panel.h"
#include "spira/ui/panels/simulation_panel.h"
#include "spira/ui/views/cell_workspace.h"
#include "spira/ui/views/path_layers.h"
#include "spira/ui/views/robot_layer.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/spiral_layer.h"
#include "spira/ui/window/comfort_features.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using ui::MainWindow;
using ui::MainWindowOptions;
using ui::Placement;
using ui::PlacementPanel;

constexpr double kDeg = M_PI / 180.0;

PlacementPanel* placementOf(MainWindow& w)
{
  auto* comfort = w.findChild<ui::ComfortFeatures*>();
  return comfort ? comfort->placementPanel() : nullptr;
}

TEST(Placement, EulerAnglesRoundTripAndRotateAboutFixedAxes)
{
  for (const Vec3& deg :
       {Vec3(0, 0, 0), Vec3(30, -45, 120), Vec3(-170, 80, -10), Vec3(90, 0, 0), Vec3(180, 0, 90)}) {
    Placement p;
    p.translation = Vec3(1.5, -2.0, 3.25);
    p.rotationDeg = deg;
    const Transform T = p.toTransform();
    const Placement q = Placement::fromTransform(T);
    EXPECT_TRUE(q.toTransform().isApprox(T, 1e-12)) << deg.transpose();
    EXPECT_NEAR((q.translation - p.translation).norm(), 0.0, 1e-12);
  }
  // X then Y then Z about the world axes: (1, 0, 0) turned 90 deg about Y lands on (0, 0, -1),
  // then 90 deg about Z leaves it there.
  Placement p;
  p.rotationDeg = Vec3(0, 90, 90);
  EXPECT_NEAR((p.toTransform() * Vec3(1, 0, 0) - Vec3(0, 0, -1)).norm(), 0.0, 1e-12);
  // (0, 1, 0): about X by 90 to (0, 0, 1), then about Z it stays: order matters.
  p.rotationDeg = Vec3(90, 0, 90);
  EXPECT_NEAR((p.toTransform() * Vec3(0, 1, 0) - Vec3(0, 0, 1)).norm(), 0.0, 1e-12);
}

TEST(Placement, DropPutsTheLowestVertexOnThePlane)
{
  TriangleMesh m = makeOpenCylinder(30.0, 60.0, 64, 12);
  Transform T = Transform::Identity();
  T.translation() = Vec3(5, 6, 40);
  T.linear() = Eigen::AngleAxisd(90 * kDeg, Vec3::UnitX()).toRotationMatrix();
  const Transform D = ui::droppedOnPlane(m, T, 2.5);
  double lowest = 1e300;
  for (const Vec3& v : m.vertices) lowest = std::min(lowest, (D * v).z());
  EXPECT_NEAR(lowest, 2.5, 1e-9);
  EXPECT_TRUE(D.linear().isApprox(T.linear()));
  EXPECT_DOUBLE_EQ(D.translation().x(), 5.0);
  // Lying on its side, the cylinder's axis is 30 mm (its radius) above the plate.
  EXPECT_NEAR(D.translation().z(), 2.5 + 30.0, 1e-9);
}

TEST(Placement, PanelMovesRotatesDropsWithUndoAndTheViewFollows)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  PlacementPanel* panel = placementOf(w);
  ASSERT_NE(panel, nullptr);
  EXPECT_FALSE(panel->dropButton()->isEnabled());  // no part yet
  ASSERT_TRUE(openAndWait(w, qpath(writeOpenCylinderStl(dir.path()))));
  EXPECT_TRUE(panel->dropButton()->isEnabled());
  panel->show();
  panel->raise();
  const QImage before = w.captureImage();
  const size_t steps = doc.undoStack().count();

  panel->field(0)->setValue(80.0);  // X
  EXPECT_DOUBLE_EQ(doc.part()->T_world_part.translation().x(), 80.0);
  EXPECT_EQ(doc.undoStack().count(), steps + 1);
  panel->field(3)->setValue(90.0);  // about X
  EXPECT_TRUE(doc.part()->T_world_part.linear().isApprox(
      Eigen::AngleAxisd(90 * kDeg, Vec3::UnitX()).toRotationMatrix(), 1e-12));
  EXPECT_EQ(doc.undoStack().count(), steps + 2);
  EXPECT_EQ(QString::fromStdString(doc.undoStack().undoText()), QStringLiteral("Rotate part"));
  // Two more steps on the same field merge into one undo step (a held arrow key).
  panel->field(3)->stepUp();
  panel->field(3)->stepDown();
  EXPECT_EQ(doc.undoStack().count(), steps + 2);

  // Turned about X, the cylinder (radius 30) reaches 30 mm below its axis: dropping lifts it.
  ASSERT_TRUE(panel->dropToSubstrate());
  EXPECT_NEAR(doc.part()->T_world_part.translation().z(), 30.0, 1e-9);
  EXPECT_NEAR(panel->field(2)->value(), 30.0, 0.005);  // the panel follows the document
  EXPECT_EQ(QString::fromStdString(doc.undoStack().undoText()), QStringLiteral("Drop part to substrate"));

  const QImage after = w.captureImage();
  EXPECT_GT(meanDifference(before, after, sceneRect(w)), 2.0) << "the 3D view did not follow the move";
  saveDocScreenshot(after, QStringLiteral("placement.png"));

  doc.undo();  // drop
  EXPECT_NEAR(doc.part()->T_world_part.translation().z(), 0.0, 1e-12);
  EXPECT_NEAR(panel->field(2)->value(), 0.0, 1e-9);
  doc.undo();  // rotate
  doc.undo();  // move
  EXPECT_TRUE(doc.part()->T_world_part.isApprox(Transform::Identity()));
  EXPECT_DOUBLE_EQ(panel->field(0)->value(), 0.0);
}

TEST(Placement, LowerBoundaryChoiceListsTheLoopsAndIsOneUndoStep)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(writeOpenCylinderStl(dir.path()))));
  PlacementPanel* panel = placementOf(w);
  QComboBox* combo = panel->lowerBoundaryCombo();
  // Automatic, then the open cylinder's two rims, lowest first.
  ASSERT_EQ(combo->count(), 3);
  EXPECT_TRUE(combo->itemText(1).contains("z 0.0 to 0.0")) << combo->itemText(1).toStdString();
  EXPECT_TRUE(combo->itemText(2).contains("z 60.0 to 60.0")) << combo->itemText(2).toStdString();
  EXPECT_EQ(combo->currentIndex(), 0);
  const size_t steps = doc.undoStack().count();
  combo->setCurrentIndex(2);
  emit combo->activated(2);
  EXPECT_EQ(doc.part()->lowerBoundaryOverride, 1);
  EXPECT_EQ(doc.undoStack().count(), steps + 1);
  doc.undo();
  EXPECT_EQ(doc.part()->lowerBoundaryOverride, Part::kAutomaticLowerBoundary);
  EXPECT_EQ(combo->currentIndex(), 0);
}

// The planner works in the part frame: a moved part keeps its spiral (moving only makes later
// stages stale), the view draws it where the part now is, and planning again gives the same path.
TEST(Placement, ThePlanFollowsThePlacedPart)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(writeOpenCylinderStl(dir.path()))));
  ASSERT_TRUE(planAndWait(w));
  ASSERT_TRUE(doc.results().spiral) << w.lastErrorMessage().toStdString();
  const auto planned = doc.results().spiral;

  Transform T = Transform::Identity();
  T.translation() = Vec3(150.0, -40.0, 0.0);
  T.linear() = Eigen::AngleAxisd(30 * kDeg, Vec3::UnitZ()).toRotationMatrix();
  doc.setPartPlacement(T);
  ASSERT_EQ(doc.results().spiral, planned);  // still valid: the path lives in the part frame

  auto* shown = vtkPolyData::SafeDownCast(w.sceneView()->spiralLayer().mapper()->GetInput());
  ASSERT_NE(shown, nullptr);
  ASSERT_EQ(shown->GetNumberOfPoints(), static_cast<vtkIdType>(planned->size()));
  for (vtkIdType i : {vtkIdType{0}, shown->GetNumberOfPoints() / 2, shown->GetNumberOfPoints() - 1}) {
    double p[3];
    shown->GetPoint(i, p);
    const Vec3 expected = T * planned->points[static_cast<size_t>(i)].position;
    EXPECT_NEAR((Vec3(p[0], p[1], p[2]) - expected).norm(), 0.0, 1e-9) << "point " << i;
  }

  ASSERT_TRUE(planAndWait(w));
  ASSERT_TRUE(doc.results().spiral);
  ASSERT_EQ(doc.results().spiral->size(), planned->size());
  for (size_t i = 0; i < planned->size(); i += 97)
    EXPECT_NEAR((doc.results().spiral->points[i].position - planned->points[i].position).norm(), 0.0, 1e-9);
}

// A scanned tube cut at a slant (its base edge rising 8 mm across): the plan refuses it and
// names the Level Base button; the button cuts it level and stands it on the plate in one undo
// step, and the levelled tube plans.
TEST(Placement, LevelBaseCutsASlantBaseLevelAndThePartThenPlans)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  TriangleMesh tube = makeOpenCylinder(30.0, 60.0, 120, 30);
  for (Vec3& v : tube.vertices) {
    const double base = 4.0 * (1.0 + v.x() / 30.0);
    v.z() = base + (60.0 - base) * v.z() / 60.0;
  }
  const std::filesystem::path file = dir.path() / "slant_tube.stl";
  writeMesh(tube, file, MeshFileFormat::StlBinary);
  ASSERT_TRUE(openAndWait(w, qpath(file)));
  PlacementPanel* panel = placementOf(w);
  ASSERT_NE(panel, nullptr);
  EXPECT_TRUE(panel->levelBaseButton()->isEnabled());
  ASSERT_TRUE(planAndWait(w));
  EXPECT_FALSE(doc.results().spiral);
  EXPECT_TRUE(w.lastErrorMessage().contains(QStringLiteral("is not level")))
      << w.lastErrorMessage().toStdString();
  EXPECT_TRUE(w.lastErrorHint().contains(QStringLiteral("Placement > Level Base")))
      << w.lastErrorHint().toStdString();

  const auto original = doc.part()->mesh;
  const size_t steps = doc.undoStack().count();
  ASSERT_TRUE(panel->levelBase());
  EXPECT_EQ(doc.undoStack().count(), steps + 1);
  EXPECT_EQ(QString::fromStdString(doc.undoStack().undoText()), QStringLiteral("Level base"));
  TriangleMesh world = *doc.part()->mesh;
  for (Vec3& v : world.vertices) v = doc.part()->T_world_part * v;
  const MeshReport report = validateMesh(world);
  ASSERT_EQ(report.boundaryLoops.size(), 2u);
  EXPECT_NEAR(report.boundaryLoops[0].zMin, 0.0, 1e-9);
  EXPECT_NEAR(report.boundaryLoops[0].zMax, 0.0, 1e-9);
  EXPECT_NEAR(report.bounds.max.z(), 52.0, 1e-9);  // 8 mm off the 60 mm tube

  ASSERT_TRUE(planAndWait(w));
  ASSERT_TRUE(doc.results().spiral) << w.lastErrorMessage().toStdString();
  saveDocScreenshot(w.captureImage(), QStringLiteral("level-base.png"));
  doc.undo();
  EXPECT_EQ(doc.part()->mesh, original);
}

// A substrate mesh from a file is read in the background, then set in one undo step; a file that
// cannot be read leaves the document as it was and says why.
TEST(Placement, ASubstrateFileIsReadInTheBackground)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  const std::filesystem::path pipe = dir.path() / "pipe.stl";
  writeMesh(makePipeAbout(32.0, 'y', 120.0), pipe, MeshFileFormat::StlBinary);
  QSignalSpy read(&w, &MainWindow::substrateRead);
  const size_t steps = doc.undoStack().count();
  ASSERT_TRUE(w.useSubstrateFile(qpath(pipe)));
  ASSERT_TRUE(waitFor([&] { return read.count() == 1; }, 30000));
  EXPECT_TRUE(read.at(0).at(1).toBool());
  ASSERT_EQ(doc.substrate()->kind, Substrate::Kind::Mesh);
  EXPECT_EQ(doc.substrate()->mesh->faceCount(), makePipeAbout(32.0, 'y', 120.0).faceCount());
  EXPECT_EQ(doc.undoStack().count(), steps + 1);

  const auto before = doc.substrate();
  ASSERT_TRUE(w.useSubstrateFile(qpath(dir.path() / "missing.stl")));
  ASSERT_TRUE(waitFor([&] { return read.count() == 2; }, 30000));
  EXPECT_FALSE(read.at(1).at(1).toBool());
  EXPECT_EQ(doc.substrate(), before);
  EXPECT_NE(w.lastErrorMessage().indexOf(QStringLiteral("missing.stl")), -1)
      << w.lastErrorMessage().toStdString();
}

// A feature added onto a pipe (the source's quarter torus on a 64 mm pipe): the Placement dock's Pipe
// button builds it on a cylinder about y in one undo step, the scene draws the pipe, and the constant-
// distance strategy plans it feasibly with its first beads measured down to the pipe.
TEST(Placement, AFeatureIsPlannedOnAPipeChosenInTheDock)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  const TriangleMesh feature =
      makeTorusOnCylinder(50.0, 15.0, 32.0, M_PI / 2, segmentsForEdge(15.0, 2.0), 39);
  const std::filesystem::path file = dir.path() / "torus_on_pipe.stl";
  writeMesh(feature, file, MeshFileFormat::StlBinary);
  ASSERT_TRUE(openAndWait(w, qpath(file)));
  PlacementPanel* panel = placementOf(w);
  ASSERT_NE(panel, nullptr);
  // On the plate its base edge, 22 to 31 mm up and not level, is refused.
  ASSERT_TRUE(planAndWait(w));
  EXPECT_FALSE(doc.results().spiral);

  const size_t steps = doc.undoStack().count();
  panel->useCylinderSubstrate(32.0, 'y');
  EXPECT_EQ(doc.undoStack().count(), steps + 1);
  ASSERT_EQ(doc.substrate()->kind, Substrate::Kind::Mesh);
  EXPECT_FALSE(panel->findChild<QPushButton*>(QStringLiteral("dropToSubstrate"))->isEnabled());
  EXPECT_EQ(panel->findChild<QComboBox*>(QStringLiteral("lowerBoundaryCombo"))->itemText(0),
            QStringLiteral("Automatic (the loop on the substrate)"));
  PlanSettings settings = *doc.settings();
  settings.decomposerId = "decomposer.constant_distance";
  doc.setPlanSettings(settings);
  ASSERT_TRUE(planAndWait(w));
  ASSERT_TRUE(doc.results().spiral) << w.lastErrorMessage().toStdString();
  ASSERT_TRUE(doc.results().reports.spiral);
  EXPECT_TRUE(doc.results().reports.spiral->feasible);
  EXPECT_GE(doc.results().reports.spiral->depositCheck.heightMin, 1.8 - 0.01);
  // The guide curve the layers were laid about is drawn through the tube: from the base edge's centre
  // (on the pipe) round the bend of radius 50 to the end face's centre.
  const Polyline& guide = doc.results().generatrices->guide;
  ASSERT_GE(guide.size(), 10u);
  for (const Vec3& q : guide) EXPECT_NEAR(std::hypot(q.x() + 50.0, q.z()), 50.0, 1.0) << q.transpose();
  EXPECT_TRUE(w.sceneView()->pathLayers().hasGuide());
  EXPECT_TRUE(w.sceneView()->pathLayers().guideActor()->GetVisibility());
  w.sceneView()->setCameraPreset(ui::CameraPreset::Iso);
  saveDocScreenshot(w.captureImage(), QStringLiteral("substrate-pipe.png"));
  panel->raise();
  QTest::qWait(50);
  EXPECT_TRUE(panel->findChild<QLabel*>(QStringLiteral("substrateLabel"))
                  ->text()
                  .contains(QStringLiteral("pipe R 32")));
  saveDocScreenshot(w.captureImage(), QStringLiteral("placement-substrate.png"));
  // The strategy's own parameters, from its schema, in the Plan dock.
  QTabWidget* tabs = w.findChild<QTabWidget*>();
  for (QTabWidget* t : w.findChildren<QTabWidget*>())
    for (int k = 0; k < t->count(); ++k)
      if (t->tabText(k) == QStringLiteral("Strategy")) tabs = t, tabs->setCurrentIndex(k);
  ASSERT_NE(tabs, nullptr);
  QTest::qWait(50);
  saveDocScreenshot(w.captureImage(), QStringLiteral("plan-constant-distance.png"));

  panel->usePlateSubstrate();
  EXPECT_EQ(doc.substrate()->kind, Substrate::Kind::Plane);
  doc.undo();
  EXPECT_EQ(doc.substrate()->kind, Substrate::Kind::Mesh);
}

// A part stored lying on its side but placed upright stands upright on the robot's table too:
// the cell holds it as the scene places it. Its motion is the upright part's, joint for joint,
// the robot is drawn upright around it and the torch lands on the drawn path.
TEST(Placement, ATiltedPartStandsUprightInTheCell)
{
  TempDir dir;
  const std::filesystem::path cellFile = sourceDir() / "resources" / "cells" / "kuka_kr16_2_table.cell";
  const Transform R(Eigen::AngleAxisd(90 * kDeg, Vec3::UnitX()));
  const TriangleMesh upright = makeOpenCylinder(30.0, 60.0, kCylinderSegments, kCylinderRings);
  writeMesh(upright, dir.path() / "upright.stl", MeshFileFormat::StlBinary);
  writeMesh(upright.transformed(R.inverse()), dir.path() / "lying.stl", MeshFileFormat::StlBinary);

  struct Run {
    std::shared_ptr<const KinematicsResult> k;
    Transform T_world_part;
    Transform base;  // the robot's base link in the scene
    std::vector<double> tcpError;
  };
  auto run = [&](const char* file, const Transform& turn) {
    Run out;
    Document doc;
    MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
    showAndWait(w);
    EXPECT_TRUE(openAndWait(w, qpath(dir.path() / file)));
    doc.setPartPlacement(turn);
    doc.setCell(readCellFile(cellFile));
    EXPECT_TRUE(planAndWait(w));
    out.k = doc.results().kinematics;
    if (!out.k) return out;
    out.T_world_part = doc.part()->T_world_part;
    ui::RobotLayer& robot = w.cellWorkspace()->robotLayer();
    out.base = robot.linkTransform(0);
    ui::SimulationPanel* sim = w.cellWorkspace()->simulationPanel();
    for (size_t i : {size_t{0}, out.k->size() / 2, out.k->size() - 1}) {
      sim->setIndex(i);
      out.tcpError.push_back(
          (robot.tcpTransform().translation() - out.T_world_part * out.k->path.points[i].position).norm());
    }
    return out;
  };
  const Run straight = run("upright.stl", Transform::Identity());
  const Run tilted = run("lying.stl", R);
  ASSERT_TRUE(straight.k && tilted.k);
  ASSERT_EQ(tilted.k->size(), straight.k->size());
  // The same motion: within a thousandth of a degree on every axis.
  double worst = 0.0;
  for (size_t i = 0; i < straight.k->size(); ++i)
    for (size_t a = 0; a < 6; ++a)
      worst = std::max(
          worst, std::abs(tilted.k->joints.points[i].robotDeg[a] - straight.k->joints.points[i].robotDeg[a]));
  EXPECT_LT(worst, 1e-3);
  // The build direction points up in the world for both, and the robot stands the same way.
  for (size_t i = 0; i < tilted.k->size(); i += 101)
    EXPECT_NEAR((tilted.T_world_part.linear() * tilted.k->path.points[i].build -
                 straight.T_world_part.linear() * straight.k->path.points[i].build)
                    .norm(),
                0.0, 1e-6);
  EXPECT_LT((tilted.base.matrix() - straight.base.matrix()).cwiseAbs().maxCoeff(), 1e-6);
  for (double e : tilted.tcpError) EXPECT_LT(e, 1e-4);
}

}  // namespace
}  // namespace spira::test
