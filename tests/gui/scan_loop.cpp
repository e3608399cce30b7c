// The scan loop in the window: the compared scan kept by the document (undo, redo, save and open bring
// it back without a new fit), its histogram in the Scan dock, a scan far off the part placed by three
// pairs picked in the 3D view, and the rest of a half-built dome re-planned from a scan of its wall.
#include <fstream>

#include <gtest/gtest.h>
#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataSet.h>
#include <vtkMapper.h>
#include <vtkRenderer.h>

#include "builtin_plugins.h"
#include "spira/base/units.h"
#include "spira/document/document.h"
#include "spira/io/import_service.h"
#include "spira/scan/built_wall.h"
#include "spira/scan/scan_simulator.h"
#include "spira/scan/scan_writer.h"
#include "spira/ui/charts/deviation_histogram.h"
#include "spira/ui/panels/scan_panel.h"
#include "spira/ui/views/continuation_layer.h"
#include "spira/ui/views/pair_picker.h"
#include "spira/ui/views/scan_layer.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/main_window.h"
#include "spira/ui/window/scan_workflow.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using ui::MainWindow;
using ui::MainWindowOptions;

std::filesystem::path junctionFile()
{
  return sourceDir() / "tests/data/real/junction_waam_mm.stl";
}

TriangleMesh junction()
{
  NullProgress progress;
  return importPart(builtinRegistry(), junctionFile(), nullptr, progress).mesh;
}

Transform misalignment(double mm, double deg)
{
  Transform T = Transform::Identity();
  T.linear() = Eigen::AngleAxisd(degToRad(deg), Vec3(0.2, -0.3, 1.0).normalized()).toRotationMatrix();
  T.translation() = Vec3(mm, -0.4 * mm, 0.2 * mm);
  return T;
}

// How far a placement is from undoing the scan's misalignment: mm at the part's farthest vertex.
double placementError(const Transform& T_part_scan, const Transform& misaligned, const TriangleMesh& part)
{
  const Transform error = T_part_scan * misaligned;
  double far = 0.0;
  for (const Vec3& v : part.vertices) far = std::max(far, (error * v - v).norm());
  return far;
}

bool compareAndWait(MainWindow& w, const std::filesystem::path& file, bool expected)
{
  QSignalSpy compared(&w, &MainWindow::scanCompared);
  if (!w.compareScanFile(qpath(file))) return false;
  if (!waitFor([&] { return compared.count() == 1; }, 60000)) return false;
  return compared.at(0).at(1).toBool() == expected;
}

TEST(ScanLoop, TheComparedScanIsKeptUndoneRedoneAndReopened)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(junctionFile())));
  const TriangleMesh mesh = junction();
  ScanErrors errors;
  errors.noiseMm = 0.05;
  errors.misalignment = misalignment(3.0, 2.0);
  std::ofstream(dir / "scan.ply", std::ios::binary)
      << pointCloudPly(simulateSurfaceScan(mesh, 1.5, errors, 3));
  ASSERT_TRUE(compareAndWait(w, dir / "scan.ply", true)) << w.lastErrorMessage().toStdString();

  ASSERT_TRUE(doc.scan());
  EXPECT_LT(placementError(doc.scan()->T_part_scan, errors.misalignment, mesh), 0.02);
  EXPECT_EQ(doc.undoStack().undoText(), "Compare scan");
  ui::ScanPanel* panel = w.scanWorkflow()->panel();
  EXPECT_EQ(panel->histogram()->binCount(), 40u);
  EXPECT_NE(panel->statsLabel()->text().indexOf(QStringLiteral("RMS")), -1);
  const ui::ScanLayer& layer = w.sceneView()->scanLayer();
  const size_t points = layer.pointCount();
  const double limit = layer.scaleLimit();
  ASSERT_GT(points, 10000u);

  w.actions().undo->trigger();
  EXPECT_FALSE(doc.scan());
  EXPECT_FALSE(layer.hasScan());
  EXPECT_FALSE(panel->histogram()->hasData());
  w.actions().redo->trigger();
  ASSERT_TRUE(doc.scan());
  EXPECT_EQ(layer.pointCount(), points);  // shown again from memory, at once

  ASSERT_TRUE(w.saveProjectAs(qpath(dir / "job.spira")));
  Document reopened;
  MainWindow w2(reopened, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w2);
  ASSERT_TRUE(w2.openProjectFile(qpath(dir / "job.spira")));
  const ui::ScanLayer& layer2 = w2.sceneView()->scanLayer();
  ASSERT_TRUE(waitFor([&] { return layer2.hasScan(); }, 60000));
  EXPECT_EQ(layer2.pointCount(), points);
  EXPECT_DOUBLE_EQ(layer2.scaleLimit(), limit);  // the same placement: no new fit
  EXPECT_NE(w2.scanWorkflow()->panel()->statusLabel()->text().indexOf(QStringLiteral("placed as recorded")),
            -1);

  // The scan file gone: the project still opens, and the messages say what is missing.
  std::filesystem::remove(dir / "scan.ply");
  Document third;
  MainWindow w3(third, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w3);
  ASSERT_TRUE(w3.openProjectFile(qpath(dir / "job.spira")));
  w3.waitUntilIdle();
  ASSERT_TRUE(waitFor([&] { return !w3.busy(); }, 30000));
  EXPECT_FALSE(w3.sceneView()->scanLayer().hasScan());
  EXPECT_TRUE(third.scan());
}

TEST(ScanLoop, AScanFarOffIsPlacedByPairsPickedInTheView)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(junctionFile())));
  const TriangleMesh mesh = junction();
  ScanErrors errors;
  errors.noiseMm = 0.05;
  errors.misalignment = misalignment(250.0, 25.0);
  const PointCloud scan = simulateSurfaceScan(mesh, 1.0, errors, 4);
  std::ofstream(dir / "far.ply", std::ios::binary) << pointCloudPly(scan);
  ASSERT_TRUE(compareAndWait(w, dir / "far.ply", false));
  EXPECT_NE(w.lastErrorMessage().indexOf(QStringLiteral("cannot place")), -1)
      << w.lastErrorMessage().toStdString();
  const ui::ScanLayer& layer = w.sceneView()->scanLayer();
  ASSERT_TRUE(layer.hasScan());
  EXPECT_FALSE(layer.aligned());  // grey, where it lies
  EXPECT_FALSE(doc.scan());
  ui::ScanPanel* panel = w.scanWorkflow()->panel();
  ASSERT_TRUE(panel->alignButton()->isEnabled());

  panel->alignButton()->click();
  ui::PairPicker* picker = w.scanWorkflow()->picker();
  ASSERT_TRUE(picker->active());
  QTest::qWait(100);
  // Three places far apart on the part, each clicked where it shows, then the same place on the scan.
  const BoundingBox box = mesh.bounds();
  const Transform T_world_part = doc.part()->T_world_part;
  // As the user does: zoomed in on each place before clicking it.
  vtkCamera* camera = w.sceneView()->renderer()->GetActiveCamera();
  // Looking at the place along its surface normal, so that it is the surface in front.
  const auto clickAt = [&](const Vec3& world, const Vec3& normal) {
    camera->SetFocalPoint(world.x(), world.y(), world.z());
    const Vec3 eye = world + 120.0 * normal;
    camera->SetPosition(eye.x(), eye.y(), eye.z());
    const Vec3 up = std::abs(normal.normalized().z()) > 0.9 ? Vec3::UnitX() : Vec3::UnitZ();
    camera->SetViewUp(up.x(), up.y(), up.z());
    camera->OrthogonalizeViewUp();
    w.sceneView()->renderer()->ResetCameraClippingRange();
    w.sceneView()->render();
    const bool hit = picker->pickAt(picker->viewPositionOf(world));
    if (!hit)
      std::printf("missed at %d,%d\n", picker->viewPositionOf(world).x(), picker->viewPositionOf(world).y());
    return hit;
  };
  const std::vector<Vec3> normals = mesh.vertexNormals();
  vtkDataSet* drawn = layer.actor()->GetMapper()->GetInput();

  for (const Vec3& corner :
       {Vec3(box.min.x(), box.max.y(), box.max.z()), Vec3(box.max.x(), box.max.y(), box.max.z()),
        Vec3(box.min.x(), box.min.y(), box.max.z())}) {
    size_t nearest = 0;
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
      if ((mesh.vertices[v] - corner).norm() < (mesh.vertices[nearest] - corner).norm()) nearest = v;
    const Vec3 n = T_world_part.linear() * normals[nearest];
    ASSERT_TRUE(clickAt(T_world_part * mesh.vertices[nearest], n));
    const Vec3 onPart = T_world_part.inverse() * picker->partPoints().back();
    // The scan's point drawn there (about 1 mm apart, fewer at its edges, whose stray points were
    // removed), clicked where it is drawn.
    const Vec3 there = T_world_part * (errors.misalignment * onPart);
    Vec3 dot = Vec3::Constant(1e9);
    double q[3];
    for (vtkIdType i = 0; i < drawn->GetNumberOfPoints(); ++i) {
      drawn->GetPoint(i, q);
      if ((Vec3(q[0], q[1], q[2]) - there).norm() < (dot - there).norm()) dot = Vec3(q[0], q[1], q[2]);
    }
    ASSERT_TRUE(clickAt(dot, T_world_part.linear() * errors.misalignment.linear() * normals[nearest]));
    EXPECT_LT((picker->scanPoints().back() - dot).norm(), 1.0);  // the dot or its neighbour in front
  }
  w.sceneView()->fitView();
  EXPECT_EQ(picker->pairCount(), 3);
  EXPECT_TRUE(panel->alignButton()->isEnabled());
  saveDocScreenshot(w.captureImage(), QStringLiteral("scan-pairs.png"));

  QSignalSpy aligned(w.scanWorkflow(), &ui::ScanWorkflow::aligned);
  panel->alignButton()->click();
  ASSERT_TRUE(waitFor([&] { return aligned.count() == 1; }, 60000)) << w.lastErrorMessage().toStdString();
  ASSERT_TRUE(aligned.at(0).at(0).toBool()) << w.lastErrorMessage().toStdString();
  ASSERT_TRUE(doc.scan());
  const double error = placementError(doc.scan()->T_part_scan, errors.misalignment, mesh);
  std::printf("placed by picked pairs and the fit: %.4f mm off at the farthest vertex\n", error);
  EXPECT_LT(error, 0.02);
  EXPECT_TRUE(layer.aligned());
  EXPECT_FALSE(picker->active());
  EXPECT_EQ(doc.undoStack().undoText(), "Align scan by points");
}

TEST(ScanLoop, ResumeFromScanDrawsTheContinuationOverThePlan)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(sourceDir() / "resources" / "samples" / "dome.stl")));
  ASSERT_TRUE(planAndWait(w)) << w.lastErrorMessage().toStdString();
  ASSERT_TRUE(doc.results().process);
  const Trajectory& plan = *doc.results().process;
  const size_t at = plan.size() / 2;
  DepositErrors errors;
  errors.relative = -0.08;
  errors.until = 0.3;
  const double beadWidth = 5.2;
  const std::vector<double> shortfall = builtShortfall(plan, at, errors);
  std::ofstream(dir / "wall.ply", std::ios::binary)
      << pointCloudPly(scanOfBuild(plan, at, shortfall, beadWidth, 3, 2.0 * beadWidth, 0.05, 9));

  ui::ScanPanel* panel = w.scanWorkflow()->panel();
  EXPECT_FALSE(panel->resumeButton()->isEnabled());  // no scan yet
  panel->placementBox()->setCurrentIndex(1);         // the cell's scanner: the part's frame
  ASSERT_TRUE(compareAndWait(w, dir / "wall.ply", true)) << w.lastErrorMessage().toStdString();
  EXPECT_TRUE(panel->resumeButton()->isEnabled());

  QSignalSpy resumed(w.scanWorkflow(), &ui::ScanWorkflow::resumed);
  ASSERT_TRUE(w.scanWorkflow()->resumeFromScan(at, beadWidth));
  ASSERT_TRUE(waitFor([&] { return resumed.count() == 1; }, 60000));
  EXPECT_TRUE(resumed.at(0).at(0).toBool()) << w.lastErrorMessage().toStdString();
  const ui::ContinuationLayer& layer = w.scanWorkflow()->continuationLayer();
  EXPECT_EQ(layer.pointCount(), plan.size() - at);
  EXPECT_TRUE(layer.actor()->GetVisibility());
  EXPECT_NE(panel->continuationLabel()->text().indexOf(QStringLiteral("made up within")), -1)
      << panel->continuationLabel()->text().toStdString();
  // 15 of the 25 beads on each generatrix laid 8 % short: 1 - 0.08 x 15 / 25 = 0.952 (docs/scans.md).
  EXPECT_NE(panel->continuationLabel()->text().indexOf(QStringLiteral("process 0.952")), -1)
      << panel->continuationLabel()->text().toStdString();
  ASSERT_TRUE(doc.scan());
  EXPECT_EQ(doc.scan()->depositedTo, at);
  panel->raise();
  w.sceneView()->setCameraPreset(ui::CameraPreset::Iso);
  QTest::qWait(50);
  saveDocScreenshot(w.captureImage(), QStringLiteral("scan-resume.png"));

  // A new plan drops the continuation: it was made for the old one.
  ASSERT_TRUE(planAndWait(w));
  EXPECT_FALSE(layer.hasContinuation());
}

}  // namespace
}  // namespace spira::test
