// File > Compare Scan: a scan of the real T-junction, moved and noised, is read in the background,
// aligned back onto the part and drawn coloured by its deviation, with the figures in the messages;
// a scan of something else is refused with the reason and nothing drawn.
#include <fstream>

#include <gtest/gtest.h>
#include <QCheckBox>
#include <QTest>

#include <vtkActor.h>

#include "builtin_plugins.h"
#include "spira/base/units.h"
#include "spira/document/document.h"
#include "spira/io/import_service.h"
#include "spira/scan/scan_simulator.h"
#include "spira/scan/scan_writer.h"
#include "spira/ui/views/scan_layer.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

#include <QSignalSpy>

namespace spira::test {
namespace {

using ui::MainWindow;
using ui::MainWindowOptions;

TEST(ScanCompare, AScanIsAlignedAndColouredByItsDeviation)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  const std::filesystem::path part = sourceDir() / "tests/data/real/junction_waam_mm.stl";
  ASSERT_TRUE(openAndWait(w, QString::fromStdString(part.string())));
  NullProgress progress;
  const TriangleMesh mesh = importPart(builtinRegistry(), part, nullptr, progress).mesh;
  ScanErrors errors;
  errors.noiseMm = 0.05;
  errors.misalignment.linear() = Eigen::AngleAxisd(degToRad(2.0), Vec3(0, 0, 1)).toRotationMatrix();
  errors.misalignment.translation() = Vec3(2.0, -1.0, 0.5);
  const PointCloud scan = simulateSurfaceScan(mesh, 1.5, errors, 3);
  std::ofstream(dir / "scan.ply", std::ios::binary) << pointCloudPly(scan);

  QSignalSpy compared(&w, &MainWindow::scanCompared);
  ASSERT_TRUE(w.compareScanFile(QString::fromStdString((dir / "scan.ply").string())));
  ASSERT_TRUE(waitFor([&] { return compared.count() == 1; }, 60000));
  ASSERT_TRUE(compared.at(0).at(1).toBool()) << w.lastErrorMessage().toStdString();
  const ui::ScanLayer& layer = w.sceneView()->scanLayer();
  EXPECT_GT(layer.pointCount(), scan.size() * 9 / 10);  // less the stray points removed
  EXPECT_TRUE(layer.actor()->GetVisibility());
  EXPECT_TRUE(layer.legend().visible());
  // The Display dock's box for it comes on with the scan.
  QCheckBox* box = nullptr;
  for (QCheckBox* b : w.findChildren<QCheckBox*>())
    if (b->text() == QStringLiteral("Compared scan")) box = b;
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(box->isEnabled());
  // The scale reaches the noise's 95th percentile: about 2 standard deviations.
  EXPECT_NEAR(layer.scaleLimit(), 1.96 * 0.05, 0.02);
  EXPECT_NE(layer.legend().title().indexOf(QStringLiteral("Scan deviation (mm)")), -1);
  w.sceneView()->setCameraPreset(ui::CameraPreset::Iso);
  QTest::qWait(50);
  saveDocScreenshot(w.captureImage(), QStringLiteral("scan-deviation.png"));

  // A scan of something 400 mm away does not overlap the part: refused, the last scan stays.
  errors.misalignment.translation() = Vec3(400.0, 0.0, 0.0);
  std::ofstream(dir / "far.ply", std::ios::binary)
      << pointCloudPly(simulateSurfaceScan(mesh, 3.0, errors, 4));
  ASSERT_TRUE(w.compareScanFile(QString::fromStdString((dir / "far.ply").string())));
  ASSERT_TRUE(waitFor([&] { return compared.count() == 2; }, 60000));
  EXPECT_FALSE(compared.at(1).at(1).toBool());
  EXPECT_NE(w.lastErrorMessage().indexOf(QStringLiteral("does not overlap the part")), -1)
      << w.lastErrorMessage().toStdString();
  EXPECT_TRUE(layer.hasScan());
}

TEST(ScanCompare, WithoutAPartThereIsNothingToCompareWith)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  for (QCheckBox* b : w.findChildren<QCheckBox*>())
    if (b->text() == QStringLiteral("Compared scan")) {
      EXPECT_FALSE(b->isEnabled());
    }
  EXPECT_FALSE(w.compareScanFile(QStringLiteral("/nonexistent/scan.ply")));
  EXPECT_NE(w.lastErrorMessage().indexOf(QStringLiteral("no part")), -1)
      << w.lastErrorMessage().toStdString();
}

}  // namespace
}  // namespace spira::test
