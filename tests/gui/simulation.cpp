// The robot side of the GUI, as a process engineer goes through it: open the sample dome, choose
// the bundled FANUC cell with its positioner, plan (the kinematics stage runs in the background
// plan), colour the spiral by dexterity, then step and play the simulation. Each step checks the
// model and the view and writes a documentation screenshot.
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <vector>

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLabel>
#include <QSlider>

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <nlohmann/json.hpp>
#include "builtin_plugins.h"

#include "spira/base/units.h"
#include "spira/document/document.h"
#include "spira/document/kinematics_result.h"
#include "spira/path/dwell.h"
#include "spira/ui/panels/cell_panel.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/simulation_clock.h"
#include "spira/ui/panels/simulation_panel.h"
#include "spira/ui/views/bead_layer.h"
#include "spira/ui/views/cell_workspace.h"
#include "spira/ui/views/interactive_quality.h"
#include "spira/ui/views/path_layers.h"
#include "spira/ui/views/point_selection.h"
#include "spira/ui/views/robot_layer.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/spiral_layer.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;

QString fanucCell()
{
  return qpath(sourceDir() / "resources" / "cells" / "fanuc_m20ia_positioner.cell");
}

double maxDifference(const Transform& a, const Transform& b)
{
  return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff();
}

Transform actorMatrix(vtkActor* actor)
{
  Transform T = Transform::Identity();
  vtkMatrix4x4* m = actor->GetUserMatrix();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) T.matrix()(r, c) = m ? m->GetElement(r, c) : (r == c ? 1.0 : 0.0);
  return T;
}

TEST(Simulation, DomeOnTheFanucPositionerCell)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(sourceDir() / "resources" / "samples" / "dome.stl")));
  ui::CellWorkspace* cells = w.cellWorkspace();
  ASSERT_NE(cells, nullptr);
  ui::RobotLayer& robot = cells->robotLayer();
  EXPECT_FALSE(robot.hasCell());
  EXPECT_FALSE(cells->simulationPanel()->hasMotion());

  // 1. The bundled cell is listed by name and set as one undo step.
  const int listed =
      cells->cellPanel()->cellCombo()->findData(QFileInfo(fanucCell()).canonicalFilePath(), Qt::UserRole);
  ASSERT_GE(listed, 1) << "the bundled FANUC cell is not in the Cell combo";
  const size_t steps = doc.undoStack().count();
  ASSERT_TRUE(cells->cellPanel()->loadCell(fanucCell()));
  ASSERT_TRUE(doc.cell());
  EXPECT_EQ(doc.undoStack().count(), steps + 1);
  ASSERT_TRUE(robot.hasCell());
  EXPECT_GE(robot.linkCount(), 7u);  // the foot and link_1..link_6
  EXPECT_TRUE(cells->cellDock()->isVisible());
  EXPECT_TRUE(cells->cellPanel()->summary()->text().contains("J5: -140 to 140 deg"));
  doc.undo();
  EXPECT_FALSE(robot.hasCell());
  doc.redo();
  ASSERT_TRUE(robot.hasCell());
  const QImage cellShot = w.captureImage();
  EXPECT_GT(distinctColours(cellShot, sceneRect(w)), 400);

  // 2. Plan: the background job solves the motion on the cell.
  ASSERT_TRUE(planAndWait(w));
  const Results& r = doc.results();
  ASSERT_TRUE(r.process);
  ASSERT_TRUE(r.kinematics) << w.lastErrorMessage().toStdString();
  const KinematicsResult& k = *r.kinematics;
  ASSERT_EQ(k.size(), r.process->size());
  EXPECT_EQ(k.path.size(), k.size());
  EXPECT_EQ(k.checks.size(), k.size());
  ASSERT_EQ(k.axes.size(), 8u);
  EXPECT_EQ(k.axes[4].name, "J5");
  EXPECT_EQ(k.axes[6].name, "E1");
  EXPECT_TRUE(k.joints.hasPositioner);
  EXPECT_EQ(k.joints.controller, "fanuc_r30ib");
  ASSERT_TRUE(r.reports.kinematics);
  const MotionStageReport& motion = r.reports.kinematics->motion;
  EXPECT_EQ(motion.reachable, k.allReachable() && motion.withinCableTwistLimit);
  size_t reached = 0;
  for (const KinematicsCheck& c : k.checks) reached += c.reachable ? 1 : 0;
  std::cout << "[ measure  ] kinematics of " << k.size() << " points: " << reached << " reachable, "
            << k.collisionCount() << " colliding, min dexterity " << motion.minDexterity
            << ", min limit margin " << motion.minLimitMarginDeg << " deg, " << r.reports.kinematics->seconds
            << " s\n";
  // The dome sits on the table centre with the build kept vertical: the arm reaches it all.
  EXPECT_EQ(reached, k.size());

  // 3. The spiral coloured by the robot's dexterity.
  ui::SpiralLayer& spiral = w.sceneView()->spiralLayer();
  EXPECT_TRUE(spiral.hasKinematics());
  ASSERT_TRUE(w.displayPanel()->setChannel(ui::SpiralChannel::Dexterity));
  EXPECT_STREQ(spiral.mapper()->GetArrayName(), "dexterity");
  EXPECT_TRUE(spiral.legend().title().startsWith("Dexterity")) << spiral.legend().title().toStdString();
  ASSERT_TRUE(w.displayPanel()->setChannel(ui::SpiralChannel::LimitMargin));
  EXPECT_TRUE(spiral.legend().title().startsWith("Joint-limit margin (deg)"));
  w.displayPanel()->setChannel(ui::SpiralChannel::Height);

  // 4. Three simulation steps: the links move, to the forward kinematics of the joints there, and
  // the torch's TCP lands on the path point it was solved for.
  ui::SimulationPanel* sim = cells->simulationPanel();
  ASSERT_TRUE(sim->hasMotion());
  EXPECT_TRUE(cells->simulationDock()->isVisible());
  sim->setIndex(0);
  std::vector<Transform> before;
  for (size_t l = 0; l < robot.linkCount(); ++l) before.push_back(robot.linkTransform(l));
  const Transform T_world_part = doc.part()->T_world_part;
  for (int step = 1; step <= 3; ++step) {
    sim->stepForward();
    ASSERT_EQ(sim->index(), static_cast<size_t>(step));
    const JointPoint& j = k.joints.points[static_cast<size_t>(step)];
    double moved = 0.0;
    for (size_t l = 0; l < robot.linkCount(); ++l) {
      const Transform T = robot.linkTransform(l);
      EXPECT_LT(maxDifference(T, robot.linkTransformAt(l, j.robotDeg, j.externalDeg)), 1e-9) << l;
      EXPECT_LT(maxDifference(actorMatrix(robot.linkActor(l)), T), 1e-9) << l;
      moved = std::max(moved, maxDifference(T, before[l]));
    }
    EXPECT_GT(moved, 1e-3) << "step " << step;
    // The positioner carries the part (and everything drawn on it); it holds the build direction
    // vertical, as the cell asks.
    const Transform T_scene_part = robot.partMotion() * T_world_part;
    const TrajectoryPoint& p = k.path.points[static_cast<size_t>(step)];
    EXPECT_GT((T_scene_part.linear() * p.build).z(), 1.0 - 1e-6) << "step " << step;
    EXPECT_LT((robot.tcpTransform().translation() - T_scene_part * p.position).norm(), 1e-4)
        << "step " << step;
    EXPECT_EQ(cells->beadLayer().shownBeadPoints(), step + 1);
    // The closure point's caption rides on the positioner with the part.
    const ui::PathLayers& layers = w.sceneView()->pathLayers();
    ASSERT_TRUE(r.generatrices && r.generatrices->hasClosurePoint);
    EXPECT_LT((layers.captionAnchor() - T_scene_part * r.generatrices->closurePoint).norm(), 1e-6)
        << "step " << step;
    EXPECT_TRUE(sim->statusText().startsWith(QStringLiteral("Point %1 of %2").arg(step + 1).arg(k.size())));
  }
  sim->stepBackward();
  EXPECT_EQ(sim->index(), 2u);

  // What playback pays per frame on the GUI thread: the pose (forward kinematics of every link,
  // actor matrices), the bead up to the point, and the render.
  QElapsedTimer frameTimer;
  frameTimer.start();
  constexpr int kFrames = 30;
  for (int f = 0; f < kFrames; ++f) sim->setIndex(static_cast<size_t>(f) * (k.size() / kFrames));
  const double poseMs = static_cast<double>(frameTimer.restart()) / kFrames;
  for (int f = 0; f < kFrames; ++f) {
    sim->setIndex(static_cast<size_t>(f) * (k.size() / kFrames));
    w.sceneView()->render();
  }
  const double frameMs = static_cast<double>(frameTimer.elapsed()) / kFrames;
  std::cout << "[ measure  ] simulation frame on " << k.size() << " points: pose and bead " << poseMs
            << " ms, with the render " << frameMs << " ms\n";

  // 5. Half-way through the build: the bead grown to the current point.
  const size_t middle = k.size() / 2;
  sim->slider()->setValue(static_cast<int>(middle));
  EXPECT_EQ(sim->index(), middle);
  EXPECT_EQ(cells->beadLayer().shownBeadPoints(), static_cast<long long>(middle + 1));
  const Vec3 target = robot.partMotion() * T_world_part * k.path.points[middle].position;
  EXPECT_LT((robot.tcpTransform().translation() - target).norm(), 1e-4);
  // Closer, as a user watching the torch would look, with the planned spiral hidden so the bead
  // deposited so far shows.
  cells->simulationDock()->raise();
  w.displayPanel()->spiralCheck()->setChecked(false);
  vtkCamera* camera = w.sceneView()->renderer()->GetActiveCamera();
  camera->SetFocalPoint(target.x(), target.y(), target.z());
  camera->Dolly(2.2);
  w.sceneView()->renderer()->ResetCameraClippingRange();
  const QImage simShot = w.captureImage();
  EXPECT_GT(distinctColours(simShot, sceneRect(w)), 400);
  EXPECT_GT(meanDifference(simShot, cellShot, sceneRect(w)), 1.0);
  saveDocScreenshot(simShot, "simulation.png");

  // A point selected elsewhere (a chart, the 3D view) poses the robot there too.
  const size_t picked = k.size() / 3;
  w.pointSelection()->select(static_cast<long long>(picked));
  EXPECT_EQ(sim->index(), picked);
  EXPECT_LT((robot.tcpTransform().translation() -
             robot.partMotion() * T_world_part * k.path.points[picked].position)
                .norm(),
            1e-4);
  sim->setIndex(middle);

  // 6. Playing at 200 x real time moves on by wall-clock time, and pauses.
  sim->setSpeed(200.0);
  auto* quality = w.sceneView()->findChild<ui::InteractiveQuality*>();
  ASSERT_NE(quality, nullptr);
  EXPECT_FALSE(quality->held());
  sim->play();
  EXPECT_TRUE(sim->playing());
  EXPECT_TRUE(quality->held());  // playback draws quick frames
  EXPECT_TRUE(quality->fast());
  waitFor([] { return false; }, 600);
  sim->pause();
  EXPECT_FALSE(sim->playing());
  EXPECT_GT(sim->index(), middle + 10);
  EXPECT_FALSE(quality->held());
  EXPECT_TRUE(waitFor([&] { return !quality->fast(); }, 3000));  // full quality once still
}

// A path of 5 points 10 mm apart at 5 mm/s, then 2 points without a speed (fallback 8 mm/s).
Trajectory straightPath()
{
  Trajectory t;
  for (int i = 0; i < 7; ++i) {
    TrajectoryPoint p;
    p.position = Vec3(10.0 * i, 0.0, 0.0);
    p.travelSpeed = i < 5 ? 5.0 : 0.0;
    t.points.push_back(p);
  }
  return t;
}

TEST(Simulation, ClockRunsTheSegmentsAtTheirTravelSpeeds)
{
  const ui::SimulationClock clock(straightPath(), 8.0);
  ASSERT_EQ(clock.size(), 7u);
  EXPECT_DOUBLE_EQ(clock.time(0), 0.0);
  EXPECT_DOUBLE_EQ(clock.time(4), 8.0);                // 40 mm at 5 mm/s
  EXPECT_DOUBLE_EQ(clock.duration(), 8.0 + 2 * 1.25);  // then 20 mm at 8 mm/s
  EXPECT_EQ(clock.indexAt(-1.0), 0u);
  EXPECT_EQ(clock.indexAt(1.99), 0u);
  EXPECT_EQ(clock.indexAt(2.0), 1u);
  EXPECT_EQ(clock.indexAt(9.3), 5u);
  EXPECT_EQ(clock.indexAt(1e9), 6u);
}

// A dwell holds the torch at its point: everything after it comes that much later, as the thermal
// model times the build.
TEST(Simulation, ClockWaitsAtADwell)
{
  Trajectory path = straightPath();
  path.extra[kDwellChannel].assign(path.size(), 0.0);
  path.extra[kDwellChannel][2] = 30.0;
  const ui::SimulationClock plain(straightPath(), 8.0), waiting(path, 8.0);
  for (size_t i = 0; i < path.size(); ++i)
    EXPECT_DOUBLE_EQ(waiting.time(i), plain.time(i) + (i > 2 ? 30.0 : 0.0)) << i;
  EXPECT_EQ(waiting.indexAt(plain.time(2) + 29.0), 2u);
}

TEST(Simulation, BeadGrowsAndCollisionsShowWhereTheyHappen)
{
  JointTrajectory joints;
  joints.points.resize(7);
  joints.points[3].collision = true;
  joints.points[5].reachable = false;
  const KinematicsResult k = makeKinematicsResult(joints, straightPath());
  vtkNew<vtkRenderer> renderer;
  ui::BeadLayer bead(renderer);
  const Transform placement(Eigen::Translation3d(0.0, 0.0, 5.0));
  bead.setMotion(&k, placement, 2.6);
  EXPECT_EQ(bead.shownBeadPoints(), 1);
  EXPECT_FALSE(bead.beadActor()->GetVisibility());  // one point: no bead yet
  bead.showUpTo(2);
  EXPECT_EQ(bead.shownBeadPoints(), 3);
  EXPECT_EQ(bead.shownFlagCount(), 0);
  EXPECT_TRUE(bead.beadActor()->GetVisibility());
  EXPECT_FALSE(bead.flagActor()->GetVisibility());
  bead.showUpTo(3);
  EXPECT_EQ(bead.shownFlagCount(), 1);
  EXPECT_TRUE(bead.flagActor()->GetVisibility());
  bead.showUpTo(6);
  EXPECT_EQ(bead.shownFlagCount(), 2);
  // The bead tube lies around the placed path: x from 0 to 60 mm, centred on z = 5.
  const std::array<double, 6> b = bead.beadBounds();
  EXPECT_NEAR(b[0], 0.0, 1e-9);
  EXPECT_NEAR(b[1], 60.0, 1e-9);
  // Ten sides: across any direction the tube spans between 2 r cos(18 deg) and 2 r.
  EXPECT_NEAR(0.5 * (b[4] + b[5]), 5.0, 1e-6);
  EXPECT_LE(b[5] - b[4], 5.2 + 1e-9);
  EXPECT_GE(b[5] - b[4], 5.2 * std::cos(kPi / 10.0) - 1e-9);
  bead.setMotion(nullptr, placement, 2.6);
  EXPECT_FALSE(bead.beadActor()->GetVisibility());
}

// Long paths are tubed chunk by chunk: at every index the bead is exactly the path laid so far,
// across chunk seams and after jumping backwards. Points 4 mm apart and a 1.5 mm tube: every
// ring vertex lies at the bead radius from the nearest laid point, and every laid point has its
// ring, so one point too many or too few shows.
TEST(Simulation, ChunkedBeadCoversThePathLaidSoFar)
{
  constexpr size_t n = 3 * ui::BeadLayer::kChunk + 40;
  Trajectory path;
  path.points.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double a = 0.1 * static_cast<double>(i);
    path.points[i].position = Vec3(40.0 * std::cos(a), 40.0 * std::sin(a), 0.3 * static_cast<double>(i));
  }
  JointTrajectory joints;
  joints.points.resize(n);
  const KinematicsResult k = makeKinematicsResult(joints, path);
  vtkNew<vtkRenderer> renderer;
  ui::BeadLayer bead(renderer);
  const double r = 1.5;
  bead.setMotion(&k, Transform::Identity(), r);
  for (size_t last : {size_t{10}, ui::BeadLayer::kChunk, ui::BeadLayer::kChunk + 1,
                      2 * ui::BeadLayer::kChunk + 7, n - 1, size_t{300}, size_t{5}}) {
    bead.showUpTo(last);
    EXPECT_EQ(bead.finishedActor()->GetVisibility(), last >= ui::BeadLayer::kChunk) << last;
    std::vector<bool> ringed(last + 1, false);
    double worst = 0.0;
    for (vtkActor* actor : {bead.beadActor(), bead.finishedActor()}) {
      if (!actor->GetVisibility()) continue;
      auto* data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputAsDataSet());
      ASSERT_NE(data, nullptr);
      for (vtkIdType v = 0; v < data->GetNumberOfPoints(); ++v) {
        double q[3];
        data->GetPoint(v, q);
        size_t nearest = 0;
        double best = 1e300;
        for (size_t i = 0; i <= last; ++i) {
          const double d = (path.points[i].position - Vec3(q[0], q[1], q[2])).norm();
          if (d < best) best = d, nearest = i;
        }
        worst = std::max(worst, std::abs(best - r));
        ringed[nearest] = true;
      }
    }
    EXPECT_LT(worst, 1e-6) << "up to point " << last;
    EXPECT_EQ(std::count(ringed.begin(), ringed.end(), true), static_cast<long>(last + 1)) << last;
  }
}

}  // namespace
}  // namespace spira::test
