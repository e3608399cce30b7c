#include "spira/ui/views/scene_view.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <QTimer>
#include <QVBoxLayout>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkLightKit.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkOutlineSource.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include "spira/document/results.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/pipeline/planned_path.h"
#include "spira/ui/views/field_layer.h"
#include "spira/ui/views/interaction_style.h"
#include "spira/ui/views/path_layers.h"
#include "spira/ui/views/scan_layer.h"
#include "spira/ui/views/spiral_layer.h"
#include "spira/ui/views/substrate_grid.h"
#include "spira/ui/views/thermal_layer.h"
#include "spira/ui/views/vtk_mesh.h"

// spira_ui is a static library: register VTK's object-factory overrides here, where the view
// that needs them lives, rather than relying on every executable's autoinit definitions.
VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkInteractionStyle);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace spira::ui {

namespace {

using Bounds = std::array<double, 6>;

bool validBounds(const Bounds& b)
{
  return b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5];
}

void setColor(vtkProperty* p, int r, int g, int b)
{
  p->SetColor(r / 255.0, g / 255.0, b / 255.0);
}

}  // namespace

struct SceneView::Scene {
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkActor> part;
  vtkNew<vtkPolyDataMapper> partMapper;
  vtkNew<vtkActor> outline;
  vtkNew<vtkOutlineSource> outlineSource;
  vtkNew<vtkActor> plate;
  vtkNew<vtkPolyDataMapper> plateMapper;
  vtkNew<vtkActor> grid;
  vtkNew<vtkPolyDataMapper> gridMapper;
  vtkNew<vtkActor> substrateMesh;
  vtkNew<vtkPolyDataMapper> substrateMeshMapper;
  vtkNew<vtkTextActor> hint;
  vtkNew<vtkAxesActor> axes;
  vtkNew<vtkOrientationMarkerWidget> marker;
  Bounds partBounds{1, -1, 1, -1, 1, -1};
  std::optional<double> substrateZ;
  bool boundingBox = false;
  CameraPreset preset = CameraPreset::Iso;
  PartStyle partStyle = PartStyle::Shaded;
  std::unique_ptr<FieldLayer> field;
  std::unique_ptr<PathLayers> paths;
  std::unique_ptr<SpiralLayer> spiral;
  std::unique_ptr<ThermalLayer> thermal;
  std::unique_ptr<ScanLayer> scan;
};

SceneView::SceneView(QWidget* parent) : QWidget(parent), scene_(std::make_unique<Scene>())
{
  Scene& s = *scene_;
  vtkWidget_ = new QVTKOpenGLNativeWidget(this);
  vtkWidget_->setRenderWindow(s.window);
  s.window->AddRenderer(s.renderer);
  // Multisampling smooths silhouettes and grid lines; VTK's FXAA pass renders black inside
  // QVTKOpenGLNativeWidget on Mesa.
  s.window->SetMultiSamples(4);
  vtkNew<QuietTrackballStyle> style;
  s.window->GetInteractor()->SetInteractorStyle(style);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(vtkWidget_);

  // A soft blue-grey gradient: light enough for dark edges and labels, dark enough that the
  // grey part does not dissolve into it.
  s.renderer->GradientBackgroundOn();
  s.renderer->SetBackground(0.70, 0.75, 0.81);
  s.renderer->SetBackground2(0.93, 0.95, 0.97);
  s.renderer->RemoveAllLights();
  vtkNew<vtkLightKit> lights;
  lights->SetKeyLightIntensity(1.0);
  lights->AddLightsToRenderer(s.renderer);
  s.renderer->SetTwoSidedLighting(true);

  s.part->SetMapper(s.partMapper);
  vtkProperty* p = s.part->GetProperty();
  setColor(p, 172, 186, 206);  // brushed steel with a blue cast
  p->SetAmbient(0.22);
  p->SetDiffuse(0.80);
  p->SetSpecular(0.35);
  p->SetSpecularPower(30.0);
  p->SetEdgeColor(0.20, 0.24, 0.30);
  p->SetLineWidth(1.0);
  // The inside of an open part in a warmer tone, so open and closed parts read differently.
  vtkNew<vtkProperty> back;
  setColor(back, 206, 188, 164);
  back->SetAmbient(0.25);
  back->SetDiffuse(0.75);
  back->SetSpecular(0.15);
  s.part->SetBackfaceProperty(back);
  s.part->VisibilityOff();
  s.renderer->AddActor(s.part);

  vtkNew<vtkPolyDataMapper> outlineMapper;
  outlineMapper->SetInputConnection(s.outlineSource->GetOutputPort());
  s.outline->SetMapper(outlineMapper);
  setColor(s.outline->GetProperty(), 214, 118, 36);
  s.outline->GetProperty()->SetLineWidth(1.5);
  s.outline->GetProperty()->LightingOff();
  s.outline->VisibilityOff();
  s.renderer->AddActor(s.outline);

  s.plate->SetMapper(s.plateMapper);
  setColor(s.plate->GetProperty(), 120, 132, 148);
  s.plate->GetProperty()->SetOpacity(0.28);
  s.plate->GetProperty()->SetSpecular(0.0);
  s.plate->VisibilityOff();
  s.renderer->AddActor(s.plate);
  s.substrateMesh->SetMapper(s.substrateMeshMapper);
  setColor(s.substrateMesh->GetProperty(), 150, 158, 170);
  s.substrateMesh->GetProperty()->SetOpacity(0.55);
  s.substrateMesh->GetProperty()->SetSpecular(0.1);
  s.substrateMesh->VisibilityOff();
  s.renderer->AddActor(s.substrateMesh);
  s.grid->SetMapper(s.gridMapper);
  setColor(s.grid->GetProperty(), 92, 104, 122);
  s.grid->GetProperty()->SetOpacity(0.45);
  s.grid->GetProperty()->LightingOff();
  s.grid->VisibilityOff();
  // Lines on the plate would flicker against it without an offset.
  s.gridMapper->SetResolveCoincidentTopologyToPolygonOffset();
  s.renderer->AddActor(s.grid);

  s.hint->SetInput("No part loaded\nFile > Import Part... (Ctrl+I)");
  vtkTextProperty* tp = s.hint->GetTextProperty();
  tp->SetFontSize(20);
  tp->SetColor(0.30, 0.34, 0.40);
  tp->SetJustificationToCentered();
  tp->SetVerticalJustificationToCentered();
  tp->SetLineSpacing(1.4);
  s.hint->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  s.hint->SetPosition(0.5, 0.5);
  s.renderer->AddViewProp(s.hint);

  for (vtkCaptionActor2D* c : {s.axes->GetXAxisCaptionActor2D(), s.axes->GetYAxisCaptionActor2D(),
                               s.axes->GetZAxisCaptionActor2D()}) {
    vtkTextProperty* t = c->GetCaptionTextProperty();
    t->SetColor(0.15, 0.17, 0.20);
    t->ShadowOff();
    t->ItalicOff();
    t->BoldOn();
  }
  s.axes->SetShaftTypeToCylinder();
  s.axes->SetCylinderRadius(0.03);
  s.axes->SetConeRadius(0.45);
  s.axes->SetTotalLength(1.0, 1.0, 1.0);
  s.marker->SetOrientationMarker(s.axes);
  s.marker->SetInteractor(s.window->GetInteractor());
  s.marker->SetViewport(0.0, 0.0, 0.16, 0.22);
  s.marker->SetEnabled(1);
  s.marker->InteractiveOff();

  s.field = std::make_unique<FieldLayer>(s.renderer, s.partMapper);
  s.paths = std::make_unique<PathLayers>(s.renderer);
  s.spiral = std::make_unique<SpiralLayer>(s.renderer);
  s.thermal = std::make_unique<ThermalLayer>(s.renderer);
  s.scan = std::make_unique<ScanLayer>(s.renderer);
  setCameraPreset(CameraPreset::Iso);
}

SceneView::~SceneView() = default;

vtkRenderer* SceneView::renderer() const
{
  return scene_->renderer;
}

bool SceneView::hasOpenGL() const
{
  return vtkWidget_->isValid();
}

bool SceneView::hasPart() const
{
  return validBounds(scene_->partBounds);
}

FieldLayer& SceneView::fieldLayer()
{
  return *scene_->field;
}

PathLayers& SceneView::pathLayers()
{
  return *scene_->paths;
}

SpiralLayer& SceneView::spiralLayer()
{
  return *scene_->spiral;
}

ScanLayer& SceneView::scanLayer()
{
  return *scene_->scan;
}

ThermalLayer& SceneView::thermalLayer()
{
  return *scene_->thermal;
}

void SceneView::showResults(const Results& r, const Transform& T_world_part)
{
  Scene& s = *scene_;
  if (r.field) {
    const bool distance = r.field->kind == "geodesic_distance";
    s.field->setField(r.field->values, distance ? tr("Geodesic distance") : tr("Harmonic field"),
                      distance ? QStringLiteral("mm") : QString());
  } else {
    s.field->setField({}, QString(), QString());
  }
  const Bounds& b = s.partBounds;
  const double diagonal = validBounds(b)
                              ? std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                                          (b[5] - b[4]) * (b[5] - b[4]))
                              : 100.0;
  s.paths->setGeneratrices(r.generatrices.get(), T_world_part, 0.012 * diagonal);
  const std::shared_ptr<const Trajectory> processed = processPathOf(r);
  const Trajectory* path = processed ? processed.get() : r.spiral.get();
  s.spiral->setTrajectory(path, processed != nullptr, planWindow(r), T_world_part);
  s.spiral->setKinematics(r.kinematics.get());
  s.spiral->setThermal(r.thermal.get(), r.reports.thermal.get());
  s.thermal->setResult(r.thermal, r.reports.thermal ? r.reports.thermal->meltingTemperature : 0.0,
                       T_world_part);
  if (!s.thermal->hasResult() && s.partStyle == PartStyle::Temperature) s.partStyle = PartStyle::Transparent;
  applyPartStyle();
  scheduleRender();
}

void SceneView::setPartStyle(PartStyle style)
{
  scene_->partStyle = style;
  applyPartStyle();
  scheduleRender();
}

PartStyle SceneView::partStyle() const
{
  return scene_->partStyle;
}

void SceneView::applyPartStyle()
{
  Scene& s = *scene_;
  const PartStyle style = s.partStyle;
  s.part->SetVisibility(validBounds(s.partBounds) && style != PartStyle::Hidden &&
                        style != PartStyle::Temperature);
  s.thermal->setVisible(style == PartStyle::Temperature);
  s.spiral->setHiddenByPart(style == PartStyle::Temperature);
  vtkProperty* p = s.part->GetProperty();
  const bool ghost = style == PartStyle::Transparent;
  p->SetOpacity(ghost ? 0.28 : 1.0);
  s.part->GetBackfaceProperty()->SetOpacity(ghost ? 0.28 : 1.0);
  // A coloured part shows its colours with little shine; the metal look keeps its highlight.
  p->SetSpecular(style == PartStyle::Field ? 0.08 : 0.35);
  s.field->setVisible(style == PartStyle::Field);
}

void SceneView::showPart(const TriangleMesh* mesh, vtkSmartPointer<vtkPolyData> shaded)
{
  Scene& s = *scene_;
  Bounds bounds{1, -1, 1, -1, 1, -1};
  if (mesh && !mesh->empty()) {
    vtkSmartPointer<vtkPolyData> poly = shaded ? shaded : toShadedPolyData(*mesh);
    poly->GetBounds(bounds.data());
    s.partMapper->SetInputData(poly);
    s.field->setSurface(poly);
    s.outlineSource->SetBounds(bounds.data());
  } else {
    s.partMapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
    s.field->setSurface(nullptr);
  }
  s.outline->SetVisibility(s.boundingBox && validBounds(bounds));
  s.hint->SetVisibility(!validBounds(bounds));
  const bool extentChanged = bounds != s.partBounds;
  s.partBounds = bounds;
  applyPartStyle();
  updateSubstrate();
  if (extentChanged) setCameraPreset(CameraPreset::Iso);
  scheduleRender();
}

void SceneView::showSubstrate(std::optional<double> z)
{
  scene_->substrateZ = z;
  updateSubstrate();
  scheduleRender();
}

void SceneView::showSubstrateMesh(const TriangleMesh* mesh)
{
  Scene& s = *scene_;
  if (mesh) s.substrateMeshMapper->SetInputData(toShadedPolyData(*mesh));
  s.substrateMesh->SetVisibility(mesh != nullptr);
  scheduleRender();
}

void SceneView::updateSubstrate()
{
  Scene& s = *scene_;
  const bool visible = s.substrateZ.has_value();
  if (visible) {
    SubstrateGrid g = makeSubstrateGrid(s.partBounds.data(), *s.substrateZ);
    s.plateMapper->SetInputData(g.plane);
    s.gridMapper->SetInputData(g.lines);
  }
  s.plate->SetVisibility(visible);
  s.grid->SetVisibility(visible);
}

void SceneView::setEdgesVisible(bool on)
{
  scene_->part->GetProperty()->SetEdgeVisibility(on);
  scheduleRender();
}

bool SceneView::edgesVisible() const
{
  return scene_->part->GetProperty()->GetEdgeVisibility() != 0;
}

void SceneView::setBoundingBoxVisible(bool on)
{
  scene_->boundingBox = on;
  scene_->outline->SetVisibility(on && validBounds(scene_->partBounds));
  scheduleRender();
}

bool SceneView::boundingBoxVisible() const
{
  return scene_->boundingBox;
}

void SceneView::setCameraPreset(CameraPreset preset)
{
  Scene& s = *scene_;
  s.preset = preset;
  vtkCamera* cam = s.renderer->GetActiveCamera();
  // Directions from the focal point to the eye, Z up (the build direction) except from the top.
  double dir[3] = {1.0, -1.2, 0.9};
  double up[3] = {0.0, 0.0, 1.0};
  switch (preset) {
    case CameraPreset::Iso:
      break;
    case CameraPreset::Front:
      dir[0] = 0.0, dir[1] = -1.0, dir[2] = 0.0;
      break;
    case CameraPreset::Side:
      dir[0] = 1.0, dir[1] = 0.0, dir[2] = 0.0;
      break;
    case CameraPreset::Top:
      dir[0] = 0.0, dir[1] = 0.0, dir[2] = 1.0;
      up[0] = 0.0, up[1] = 1.0, up[2] = 0.0;
      break;
  }
  cam->SetFocalPoint(0.0, 0.0, 0.0);
  cam->SetPosition(dir);
  cam->SetViewUp(up);
  fitView();
}

vtkActor* SceneView::partActor() const
{
  return scene_->part;
}

void SceneView::fitView()
{
  fitViewIncluding(BoundingBox());
}

void SceneView::fitViewIncluding(const BoundingBox& extra)
{
  Scene& s = *scene_;
  Bounds b = s.partBounds;
  if (!extra.empty()) {
    if (!validBounds(b))
      b = {extra.min.x(), extra.max.x(), extra.min.y(), extra.max.y(), extra.min.z(), extra.max.z()};
    for (int k = 0; k < 3; ++k)
      b[2 * k] = std::min(b[2 * k], extra.min[k]), b[2 * k + 1] = std::max(b[2 * k + 1], extra.max[k]);
  }
  if (!validBounds(b)) {
    const double z = s.substrateZ.value_or(0.0);
    b = {-80.0, 80.0, -80.0, 80.0, z, z};  // the plate drawn when there is no part
  }
  vtkCamera* cam = s.renderer->GetActiveCamera();
  // Frame the box's corners rather than its bounding sphere (vtkRenderer::ResetCamera), which
  // leaves a part small in the window: place the eye on the current view axis at the nearest
  // distance from which every corner is inside the view, with a margin.
  double d[3], up[3];
  cam->GetDirectionOfProjection(d);
  cam->OrthogonalizeViewUp();
  cam->GetViewUp(up);
  double right[3];
  vtkMath::Cross(d, up, right);
  const double c[3] = {0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])};
  const int* size = s.renderer->GetSize();
  const double aspect = size[0] > 0 && size[1] > 0 ? double(size[0]) / size[1] : 1.6;
  const double t = std::tan(0.5 * vtkMath::RadiansFromDegrees(cam->GetViewAngle())) * 0.86;
  double distance = 0.0;
  for (int i = 0; i < 8; ++i) {
    const double p[3] = {b[i & 1] - c[0], b[2 + ((i >> 1) & 1)] - c[1], b[4 + ((i >> 2) & 1)] - c[2]};
    const double x = std::abs(vtkMath::Dot(p, right)), y = std::abs(vtkMath::Dot(p, up));
    const double z = vtkMath::Dot(p, d);
    distance = std::max({distance, y / t - z, x / (t * aspect) - z});
  }
  distance = std::max(distance, 1.0);
  cam->SetFocalPoint(c);
  cam->SetPosition(c[0] - distance * d[0], c[1] - distance * d[1], c[2] - distance * d[2]);
  s.renderer->ResetCameraClippingRange();
  scheduleRender();
}

void SceneView::scheduleRender()
{
  // Several changes usually arrive together (part, plate, camera): render once for all of them,
  // which matters on million-triangle parts and software OpenGL.
  // A real timer, not a queued call (which QTimer::singleShot(0) is): queued calls run back to
  // back with the other posted events (a relayout, the results' panels), and the frame would add
  // to their stall. 10 ms later the event loop has taken the input and timers that waited behind
  // the change (new results take 20-40 ms to reach the panels) before the frame blocks it again.
  constexpr int kRenderDelayMs = 10;
  if (renderPending_) return;
  renderPending_ = true;
  if (!renderTimer_) {
    renderTimer_ = new QTimer(this);
    renderTimer_->setSingleShot(true);
    renderTimer_->setInterval(kRenderDelayMs);
    connect(renderTimer_, &QTimer::timeout, this, [this] {
      if (renderPending_) render();
    });
  }
  renderTimer_->start();
}

void SceneView::render()
{
  renderPending_ = false;
  if (vtkWidget_ && vtkWidget_->isValid())
    scene_->window->Render();
  else if (vtkWidget_)
    vtkWidget_->update();
}

QImage SceneView::grabImage()
{
  render();
  return vtkWidget_->grabFramebuffer();
}

}  // namespace spira::ui
