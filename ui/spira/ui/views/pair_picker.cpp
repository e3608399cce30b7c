#include "spira/ui/views/pair_picker.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <QMouseEvent>

#include <cmath>

#include "spira/ui/views/scene_view.h"

namespace spira::ui {

namespace {

constexpr int kClickSlop = 4;          // px a press may move and still be a click
constexpr double kScanPickPixels = 6;  // how near the click a scan point is drawn to be picked

}  // namespace

PairPicker::PairPicker(SceneView& view, QObject* parent) : QObject(parent), view_(view)
{
  partPicker_->PickFromListOn();
  partPicker_->SetTolerance(0.002);
  mapper_->SetInputData(markers_);
  actor_->SetMapper(mapper_);
  actor_->GetProperty()->SetPointSize(14.0);
  actor_->GetProperty()->SetRenderPointsAsSpheres(true);
  actor_->GetProperty()->LightingOff();
  actor_->PickableOff();
  actor_->VisibilityOff();
  view_.renderer()->AddActor(actor_);
  widget_ = view_.vtkWidget();
  if (widget_) widget_->installEventFilter(this);
}

PairPicker::~PairPicker() = default;

void PairPicker::start(vtkActor* part, vtkActor* scan)
{
  partPicker_->InitializePickList();
  if (part) partPicker_->AddPickList(part);
  scan_ = scan;
  partPoints_.clear();
  scanPoints_.clear();
  active_ = true;
  updateMarkers();
}

void PairPicker::stop()
{
  active_ = false;
  partPoints_.clear();
  scanPoints_.clear();
  updateMarkers();
}

bool PairPicker::pickAt(const QPoint& pos)
{
  if (!active_ || !widget_) return false;
  const double dpr = widget_->devicePixelRatioF();
  const double x = pos.x() * dpr, y = (widget_->height() - pos.y() - 1) * dpr;
  double world[3];
  if (expecting() == Expect::Part) {
    if (!partPicker_->Pick(x, y, 0.0, view_.renderer()) || !partPicker_->GetActor()) {
      emit missed();
      return false;
    }
    partPicker_->GetPickPosition(world);
    partPoints_.push_back(Vec3(world[0], world[1], world[2]));
  } else {
    const std::optional<Vec3> hit = frontScanPointAt(x, y);
    if (!hit) {
      emit missed();
      return false;
    }
    scanPoints_.push_back(*hit);
  }
  updateMarkers();
  emit picked();
  return true;
}

// The scan point itself, not where a ray met it (the pair must be a measured point), and of the points
// drawn within a few pixels of the click the one nearest the eye: the one the user sees, not one on
// the far side of a tube that happens to lie closer to the ray.
std::optional<Vec3> PairPicker::frontScanPointAt(double x, double y) const
{
  vtkActor* scan = scan_;
  if (!scan || !scan->GetVisibility() || !scan->GetMapper()) return std::nullopt;
  vtkDataSet* data = scan->GetMapper()->GetInput();
  if (!data || data->GetNumberOfPoints() == 0) return std::nullopt;
  vtkRenderer* r = view_.renderer();
  const int* size = r->GetSize();
  if (size[0] <= 0 || size[1] <= 0) return std::nullopt;
  const double aspect = double(size[0]) / double(size[1]);
  vtkMatrix4x4* m = r->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
  const int* origin = r->GetOrigin();
  const double px = x - origin[0], py = y - origin[1];
  const double tolerance = kScanPickPixels * widget_->devicePixelRatioF();
  double bestDepth = 2.0;
  vtkIdType best = -1;
  double p[3];
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    data->GetPoint(i, p);
    const double w = m->GetElement(3, 0) * p[0] + m->GetElement(3, 1) * p[1] + m->GetElement(3, 2) * p[2] +
                     m->GetElement(3, 3);
    if (w <= 0.0) continue;
    const auto ndc = [&](int row) {
      return (m->GetElement(row, 0) * p[0] + m->GetElement(row, 1) * p[1] + m->GetElement(row, 2) * p[2] +
              m->GetElement(row, 3)) /
             w;
    };
    const double sx = 0.5 * (ndc(0) + 1.0) * size[0], sy = 0.5 * (ndc(1) + 1.0) * size[1];
    if (std::abs(sx - px) > tolerance || std::abs(sy - py) > tolerance) continue;
    const double depth = ndc(2);
    if (depth < bestDepth) bestDepth = depth, best = i;
  }
  if (best < 0) return std::nullopt;
  data->GetPoint(best, p);
  return Vec3(p[0], p[1], p[2]);
}

QPoint PairPicker::viewPositionOf(const Vec3& world) const
{
  if (!widget_) return {};
  vtkRenderer* r = view_.renderer();
  r->SetWorldPoint(world.x(), world.y(), world.z(), 1.0);
  r->WorldToDisplay();
  double d[3];
  r->GetDisplayPoint(d);
  const double dpr = widget_->devicePixelRatioF();
  return QPoint(int(std::lround(d[0] / dpr)), int(std::lround(widget_->height() - 1 - d[1] / dpr)));
}

bool PairPicker::eventFilter(QObject* watched, QEvent* event)
{
  if (active_ && watched == widget_) {
    if (event->type() == QEvent::MouseButtonPress) {
      auto* m = static_cast<QMouseEvent*>(event);
      if (m->button() == Qt::LeftButton) press_ = m->pos();
    } else if (event->type() == QEvent::MouseButtonRelease) {
      auto* m = static_cast<QMouseEvent*>(event);
      if (m->button() == Qt::LeftButton && (m->pos() - press_).manhattanLength() <= kClickSlop)
        pickAt(m->pos());
    }
  }
  return QObject::eventFilter(watched, event);
}

void PairPicker::updateMarkers()
{
  markers_->Initialize();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  colours->SetName("colour");
  const auto add = [&](const Vec3& p, unsigned char r, unsigned char g, unsigned char b) {
    const vtkIdType id = points->InsertNextPoint(p.x(), p.y(), p.z());
    vertices->InsertNextCell(1);
    vertices->InsertCellPoint(id);
    const unsigned char c[3] = {r, g, b};
    colours->InsertNextTypedTuple(c);
  };
  for (const Vec3& p : partPoints_) add(p, 30, 90, 220);
  for (const Vec3& p : scanPoints_) add(p, 240, 140, 20);
  markers_->SetPoints(points);
  markers_->SetVerts(vertices);
  markers_->GetPointData()->SetScalars(colours);
  mapper_->SetScalarModeToUsePointData();
  mapper_->SetColorModeToDirectScalars();
  actor_->SetVisibility(active_ && points->GetNumberOfPoints() > 0);
  view_.scheduleRender();
}

}  // namespace spira::ui
