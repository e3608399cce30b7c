// The 3D view: camera presets look along the stated axes, fit-to-view frames every corner of the
// part, toggles change what is drawn, and the substrate plate follows the part.
#include <array>
#include <cmath>

#include <QAction>

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include "builtin_plugins.h"

#include "spira/document/document.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/substrate_grid.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"

namespace spira::test {
namespace {

using spira::ui::CameraPreset;
using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;
using spira::ui::SceneView;

std::array<double, 3> viewDirection(SceneView* view)
{
  std::array<double, 3> d{};
  view->renderer()->GetActiveCamera()->GetDirectionOfProjection(d.data());
  return d;
}

// Display coordinates of the 8 corners of `b`, as fractions of the viewport.
std::array<std::array<double, 2>, 8> projectedCorners(vtkRenderer* ren, const double b[6])
{
  std::array<std::array<double, 2>, 8> out{};
  const int* size = ren->GetSize();
  for (int i = 0; i < 8; ++i) {
    ren->SetWorldPoint(b[i & 1], b[2 + ((i >> 1) & 1)], b[4 + ((i >> 2) & 1)], 1.0);
    ren->WorldToDisplay();
    double p[3];
    ren->GetDisplayPoint(p);
    out[i] = {p[0] / size[0], p[1] / size[1]};
  }
  return out;
}

class SceneViewTest : public ::testing::Test {
 protected:
  void SetUp() override
  {
    window_ = std::make_unique<MainWindow>(doc_, builtinRegistry(), MainWindowOptions{false, false});
    showAndWait(*window_);
    Part part;
    part.name = "cone";
    part.mesh = std::make_shared<const TriangleMesh>(makeOpenCone(40.0, 20.0, 90.0, 48, 10));
    doc_.setPart(part, "Import Part");
    view_ = window_->sceneView();
  }
  Document doc_;
  std::unique_ptr<MainWindow> window_;
  SceneView* view_ = nullptr;
};

TEST_F(SceneViewTest, PresetsLookAlongTheirAxesWithZUp)
{
  view_->setCameraPreset(CameraPreset::Top);
  auto d = viewDirection(view_);
  EXPECT_NEAR(d[2], -1.0, 1e-9);
  view_->setCameraPreset(CameraPreset::Front);
  d = viewDirection(view_);
  EXPECT_NEAR(d[1], 1.0, 1e-9);
  double up[3];
  view_->renderer()->GetActiveCamera()->GetViewUp(up);
  EXPECT_NEAR(up[2], 1.0, 1e-9);
  window_->actions().viewSide->trigger();
  d = viewDirection(view_);
  EXPECT_NEAR(d[0], -1.0, 1e-9);
  window_->actions().viewIso->trigger();
  d = viewDirection(view_);
  EXPECT_LT(d[0], -0.3);
  EXPECT_GT(d[1], 0.3);
  EXPECT_LT(d[2], -0.3);  // looking down onto the substrate
}

TEST_F(SceneViewTest, FitFramesEveryCornerOfThePartAndFillsTheView)
{
  const double bounds[6] = {-40, 40, -40, 40, 0, 90};
  for (CameraPreset preset :
       {CameraPreset::Iso, CameraPreset::Front, CameraPreset::Top, CameraPreset::Side}) {
    view_->setCameraPreset(preset);
    // Zoom far out and pan away, then fit again.
    vtkCamera* cam = view_->renderer()->GetActiveCamera();
    cam->Dolly(0.2);
    cam->Azimuth(10.0);
    window_->actions().fitView->trigger();
    double minX = 1, maxX = 0, minY = 1, maxY = 0;
    for (const auto& p : projectedCorners(view_->renderer(), bounds)) {
      EXPECT_GT(p[0], 0.0);
      EXPECT_LT(p[0], 1.0);
      EXPECT_GT(p[1], 0.0);
      EXPECT_LT(p[1], 1.0);
      minX = std::min(minX, p[0]), maxX = std::max(maxX, p[0]);
      minY = std::min(minY, p[1]), maxY = std::max(maxY, p[1]);
    }
    // Fitted, not merely visible: the box spans most of the view in one direction.
    EXPECT_GT(std::max(maxX - minX, maxY - minY), 0.7) << "preset " << static_cast<int>(preset);
  }
}

TEST_F(SceneViewTest, ToggleActionsChangeWhatIsDrawn)
{
  window_->actions().showEdges->setChecked(true);
  EXPECT_TRUE(view_->edgesVisible());
  window_->actions().showEdges->setChecked(false);
  EXPECT_FALSE(view_->edgesVisible());
  window_->actions().showBoundingBox->setChecked(true);
  EXPECT_TRUE(view_->boundingBoxVisible());
  // For looking at the pictures: SPIRA_GUI_SCREENSHOT_DIR=/some/folder keeps them.
  const QString keep = qEnvironmentVariable("SPIRA_GUI_SCREENSHOT_DIR");
  if (!keep.isEmpty()) {
    window_->actions().showEdges->setChecked(true);
    window_->captureImage().save(keep + "/cone_edges_bbox.png");
    window_->actions().viewFront->trigger();
    window_->captureImage().save(keep + "/cone_front.png");
    window_->actions().showEdges->setChecked(false);
  }
  int visible = 0;
  vtkActorCollection* actors = view_->renderer()->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor()) visible += a->GetVisibility() ? 1 : 0;
  window_->actions().showSubstrate->setChecked(false);
  int visibleWithoutPlate = 0;
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor()) visibleWithoutPlate += a->GetVisibility() ? 1 : 0;
  EXPECT_EQ(visibleWithoutPlate, visible - 2);  // plate and grid lines
}

TEST(SubstrateGrid, PlateCoversTheFootprintAtTheSubstrateHeightWithRoundSpacing)
{
  const double bounds[6] = {-13.0, 47.0, 5.0, 35.0, 2.0, 80.0};
  const ui::SubstrateGrid g = ui::makeSubstrateGrid(bounds, -4.5);
  double pb[6];
  g.plane->GetBounds(pb);
  EXPECT_LE(pb[0], bounds[0]);
  EXPECT_GE(pb[1], bounds[1]);
  EXPECT_LE(pb[2], bounds[2]);
  EXPECT_GE(pb[3], bounds[3]);
  EXPECT_DOUBLE_EQ(pb[4], -4.5);
  EXPECT_DOUBLE_EQ(pb[5], -4.5);
  EXPECT_LT(pb[1] - pb[0], 3.0 * 60.0);  // a plate, not a floor
  const double mantissa = g.spacing / std::pow(10.0, std::floor(std::log10(g.spacing)));
  EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9)
      << g.spacing;
  EXPECT_NEAR(std::fmod(pb[0] + 1e6 * g.spacing, g.spacing), 0.0, 1e-6);  // lines on round coordinates

  EXPECT_DOUBLE_EQ(ui::niceGridSpacing(100.0, 10), 10.0);
  EXPECT_DOUBLE_EQ(ui::niceGridSpacing(130.0, 10), 20.0);
  EXPECT_DOUBLE_EQ(ui::niceGridSpacing(0.3, 10), 0.05);
  EXPECT_DOUBLE_EQ(ui::niceGridSpacing(450.0, 10), 50.0);
}

}  // namespace
}  // namespace spira::test
