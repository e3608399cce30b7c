#include "spira/ui/views/path_inspector.h"

#include <algorithm>
#include <cmath>

#include <QEvent>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QMouseEvent>
#include <QStatusBar>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkAxis.h>
#include <vtkCellPicker.h>
#include <vtkChartXY.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTable.h>

#include "spira/base/units.h"
#include "spira/document/results.h"
#include "spira/pipeline/document_plan.h"
#include "spira/pipeline/planned_path.h"
#include "spira/ui/charts/process_chart.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/views/frame_glyphs.h"
#include "spira/ui/views/offending_points.h"
#include "spira/ui/views/point_selection.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/spiral_layer.h"
#include "spira/ui/views/thermal_risk_zones.h"

namespace spira::ui {

namespace {

// A click is a press and release this close together (pixels); more is a drag (rotate, pan).
constexpr int kClickSlop = 4;

ProcessChart::Row panelRow(int k)
{
  return k == 0 ? ProcessChart::HeightRow : ProcessChart::TravelSpeedRow;
}

}  // namespace

PathInspector::PathInspector(PointSelection* selection, SceneView* view, ProcessChart* chart, LogPanel* log,
                             QStatusBar* status, QObject* parent)
    : QObject(parent), view_(view), chart_(chart), log_(log), selection_(selection)
{
  glyphs_ = std::make_unique<FrameGlyphs>(view_->renderer());

  // The marker: a bright sphere with a dark rim of its own size, legible on every channel colour.
  sphere_->SetThetaResolution(24);
  sphere_->SetPhiResolution(16);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere_->GetOutputPort());
  marker_->SetMapper(mapper);
  marker_->GetProperty()->SetColor(0.9, 0.63, 0.0);  // the charts' cursor colour
  marker_->GetProperty()->SetSpecular(0.4);
  marker_->GetProperty()->SetEdgeVisibility(false);
  marker_->SetPickable(false);
  marker_->SetVisibility(false);
  view_->renderer()->AddActor(marker_);

  picker_->PickFromListOn();
  picker_->AddPickList(view_->spiralLayer().actor());
  picker_->SetTolerance(0.006);
  viewWidget_ = view_->vtkWidget();
  if (viewWidget_) viewWidget_->installEventFilter(this);

  for (int k = 0; k < 2; ++k) {
    vtkTable* t = cursorTables_[static_cast<size_t>(k)];
    for (const char* name : {"s", "value"}) {
      vtkNew<vtkDoubleArray> a;
      a->SetName(name);
      t->AddColumn(a);
    }
    vtkPlot* line = chart_->chart(panelRow(k))->AddPlot(vtkChart::LINE);
    line->SetInputData(t, 0, 1);
    line->SetColor(230, 160, 0, 255);
    line->SetWidth(2.0);
    line->SetVisible(false);
    line->SetSelectable(false);
    cursorPlots_[static_cast<size_t>(k)] = line;
  }
  chartWidget_ = chart_->vtkWidget();
  if (chartWidget_) chartWidget_->installEventFilter(this);

  if (log_) {
    logList_ = log_->list();
    if (logList_)
      connect(logList_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        const QVariant v = item->data(kPointRole);
        if (v.isValid()) selection_->select(v.toLongLong());
      });
  }
  if (status) {
    status_ = new QLabel(status);
    status_->setObjectName(QStringLiteral("selectedPointLabel"));
    status->addWidget(status_, 1);
  }
  connect(selection_, &PointSelection::changed, this, &PathInspector::onSelectionChanged);
}

PathInspector::~PathInspector()
{
  view_->renderer()->RemoveActor(marker_);
}

void PathInspector::setResults(const Results& results, const Transform& T_world_part)
{
  const std::shared_ptr<const Trajectory> processed = processPathOf(results);
  const std::shared_ptr<const Trajectory> path = processed ? processed : results.spiral;
  const bool changed = path != path_ || !T_world_part.isApprox(T_world_part_);
  hasSpeeds_ = processed != nullptr;
  if (changed) {
    const bool fresh = path != path_;
    path_ = path;
    T_world_part_ = T_world_part;
    abscissa_.clear();
    if (path_) {
      abscissa_.reserve(path_->size());
      double s = 0.0;
      for (size_t i = 0; i < path_->size(); ++i) {
        if (i > 0) s += (path_->points[i].position - path_->points[i - 1].position).norm();
        abscissa_.push_back(s);
      }
    }
    length_ = abscissa_.empty() ? 0.0 : abscissa_.back();
    Eigen::AlignedBox3d box;
    if (path_)
      for (const TrajectoryPoint& q : path_->points) box.extend(q.position);
    pathDiagonal_ = box.isEmpty() ? 0.0 : box.diagonal().norm();
    glyphs_->setTrajectory(path_, T_world_part_);
    if (fresh && results.process) listOffenders(results);
  }
  if (!path_ || selection_->index() >= static_cast<long long>(path_->size()))
    selection_->clear();
  else
    onSelectionChanged(selection_->index());
}

void PathInspector::setFramesVisible(bool on)
{
  glyphs_->setVisible(on);
  view_->scheduleRender();
}

long long PathInspector::nearestToAbscissa(double s) const
{
  if (abscissa_.empty()) return -1;
  const auto it = std::lower_bound(abscissa_.begin(), abscissa_.end(), s);
  if (it == abscissa_.end()) return static_cast<long long>(abscissa_.size()) - 1;
  const long long i = it - abscissa_.begin();
  if (i > 0 && s - abscissa_[static_cast<size_t>(i - 1)] < *it - s) return i - 1;
  return i;
}

Vec3 PathInspector::worldPoint(long long i) const
{
  return T_world_part_ * path_->points.at(static_cast<size_t>(i)).position;
}

long long PathInspector::nearestTo(const Vec3& world) const
{
  if (!path_ || path_->empty()) return -1;
  const Vec3 p = T_world_part_.inverse() * world;
  long long best = -1;
  double bestD = HUGE_VAL;
  for (size_t i = 0; i < path_->size(); ++i) {
    const double d = (path_->points[i].position - p).squaredNorm();
    if (d < bestD) bestD = d, best = static_cast<long long>(i);
  }
  return best;
}

long long PathInspector::indexAtChartPosition(const QPoint& pos) const
{
  if (!chartWidget_ || abscissa_.empty() || !chartWidget_->isVisible()) return -1;
  const double dpr = chartWidget_->devicePixelRatioF();
  const double sx = pos.x() * dpr, sy = (chartWidget_->height() - pos.y()) * dpr;
  for (int k = 0; k < 2; ++k) {
    vtkChartXY* c = chart_->chart(panelRow(k));
    vtkAxis* x = c->GetAxis(vtkAxis::BOTTOM);
    vtkAxis* y = c->GetAxis(vtkAxis::LEFT);
    const float* x1 = x->GetPoint1();
    const float* x2 = x->GetPoint2();
    const float* y1 = y->GetPoint1();
    const float* y2 = y->GetPoint2();
    if (sx < x1[0] || sx > x2[0] || sy < std::min(y1[1], y2[1]) || sy > std::max(y1[1], y2[1])) continue;
    const double unit = chart_->abscissaUnit() == QLatin1String("m") ? 1000.0 : 1.0;
    const double s = x->GetMinimum() + (sx - x1[0]) / (x2[0] - x1[0]) * (x->GetMaximum() - x->GetMinimum());
    return nearestToAbscissa(s * unit);
  }
  return -1;
}

QPoint PathInspector::chartPositionOf(long long i) const
{
  if (!chartWidget_ || !path_) return {};
  vtkChartXY* c = chart_->chart(ProcessChart::HeightRow);
  vtkAxis* x = c->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* y = c->GetAxis(vtkAxis::LEFT);
  const double unit = chart_->abscissaUnit() == QLatin1String("m") ? 1000.0 : 1.0;
  const double s = abscissa_.at(static_cast<size_t>(i)) / unit;
  const double h = path_->points.at(static_cast<size_t>(i)).height;
  const double sx = x->GetPoint1()[0] + (s - x->GetMinimum()) / (x->GetMaximum() - x->GetMinimum()) *
                                            (x->GetPoint2()[0] - x->GetPoint1()[0]);
  const double sy = y->GetPoint1()[1] + (h - y->GetMinimum()) / (y->GetMaximum() - y->GetMinimum()) *
                                            (y->GetPoint2()[1] - y->GetPoint1()[1]);
  const double dpr = chartWidget_->devicePixelRatioF();
  return QPoint(static_cast<int>(std::lround(sx / dpr)),
                static_cast<int>(std::lround(chartWidget_->height() - sy / dpr)));
}

long long PathInspector::pickInView(const QPoint& pos) const
{
  QVTKOpenGLNativeWidget* w = viewWidget_;
  if (!w || !path_ || !view_->spiralLayer().actor()->GetVisibility()) return -1;
  const double dpr = w->devicePixelRatioF();
  const double x = pos.x() * dpr, y = (w->height() - pos.y() - 1) * dpr;
  if (!picker_->Pick(x, y, 0.0, view_->renderer())) return -1;
  double world[3];
  picker_->GetPickPosition(world);
  return nearestTo(Vec3(world[0], world[1], world[2]));
}

QPoint PathInspector::viewPositionOf(long long i) const
{
  QVTKOpenGLNativeWidget* w = viewWidget_;
  if (!w || !path_) return {};
  const Vec3 p = worldPoint(i);
  vtkRenderer* r = view_->renderer();
  r->SetWorldPoint(p.x(), p.y(), p.z(), 1.0);
  r->WorldToDisplay();
  double d[3];
  r->GetDisplayPoint(d);
  const double dpr = w->devicePixelRatioF();
  return QPoint(static_cast<int>(std::lround(d[0] / dpr)),
                static_cast<int>(std::lround(w->height() - 1 - d[1] / dpr)));
}

bool PathInspector::markerVisible() const
{
  return marker_->GetVisibility() != 0;
}

Vec3 PathInspector::markerPosition() const
{
  const double* c = sphere_->GetCenter();
  return Vec3(c[0], c[1], c[2]);
}

double PathInspector::markerRadius() const
{
  return sphere_->GetRadius();
}

std::optional<double> PathInspector::chartCursor() const
{
  if (!cursorPlots_[0]->GetVisible() || cursorTables_[0]->GetNumberOfRows() < 1) return std::nullopt;
  return cursorTables_[0]->GetValue(0, 0).ToDouble();
}

bool PathInspector::eventFilter(QObject* watched, QEvent* event)
{
  if (watched == chartWidget_) {
    if (event->type() == QEvent::MouseButtonPress) {
      auto* m = static_cast<QMouseEvent*>(event);
      if (m->button() == Qt::LeftButton) chartPress_ = m->pos();
    } else if (event->type() == QEvent::MouseButtonRelease) {
      auto* m = static_cast<QMouseEvent*>(event);
      if (m->button() == Qt::LeftButton && (m->pos() - chartPress_).manhattanLength() <= kClickSlop) {
        const long long i = indexAtChartPosition(m->pos());
        if (i >= 0) selection_->select(i);
      }
    }
  }
  if (watched == viewWidget_) {
    if (event->type() == QEvent::MouseButtonPress) {
      auto* m = static_cast<QMouseEvent*>(event);
      if (m->button() == Qt::LeftButton) viewPress_ = m->pos();
    } else if (event->type() == QEvent::MouseButtonRelease) {
      auto* m = static_cast<QMouseEvent*>(event);
      // A click on the spiral selects; a drag rotates the view as before.
      if (m->button() == Qt::LeftButton && (m->pos() - viewPress_).manhattanLength() <= kClickSlop) {
        const long long i = pickInView(m->pos());
        if (i >= 0) selection_->select(i);
      }
    }
  }
  return QObject::eventFilter(watched, event);
}

void PathInspector::onSelectionChanged(long long index)
{
  const bool on = path_ && index >= 0 && index < static_cast<long long>(path_->size());
  marker_->SetVisibility(on);
  if (on) {
    const Vec3 p = worldPoint(index);
    // Sized to the path (not to the scene, which a robot cell makes ten times larger): a few
    // bead widths on a part of a few hundred millimetres.
    sphere_->SetRadius(std::clamp(0.025 * pathDiagonal_, 1.0, 50.0));
    sphere_->SetCenter(p.x(), p.y(), p.z());
  }
  updateChartCursor();
  if (status_) {
    if (!on) {
      status_->clear();
    } else {
      const TrajectoryPoint& q = path_->points[static_cast<size_t>(index)];
      const QLocale loc;
      QString text = tr("Point %1 of %2 (revolution %3): s = %4 mm, h = %5 mm")
                         .arg(loc.toString(index), loc.toString(static_cast<qulonglong>(path_->size())))
                         .arg(q.revolution + 1)
                         .arg(loc.toString(abscissa_[static_cast<size_t>(index)], 'f', 1),
                              loc.toString(q.height, 'f', 3));
      if (hasSpeeds_)
        text += tr(", TS = %1 mm/s, WFS = %2 m/min")
                    .arg(loc.toString(q.travelSpeed, 'f', 2),
                         loc.toString(q.wireFeed / toInternalFactor("m/min"), 'f', 2));
      status_->setText(text);
    }
  }
  view_->scheduleRender();
}

void PathInspector::updateChartCursor()
{
  const long long index = selection_->index();
  const bool on = path_ && index >= 0 && index < static_cast<long long>(abscissa_.size());
  const double unit = chart_->abscissaUnit() == QLatin1String("m") ? 1000.0 : 1.0;
  for (int k = 0; k < 2; ++k) {
    vtkPlot* plot = cursorPlots_[static_cast<size_t>(k)];
    plot->SetVisible(on);
    if (!on) continue;
    vtkAxis* y = chart_->chart(panelRow(k))->GetAxis(vtkAxis::LEFT);
    vtkTable* t = cursorTables_[static_cast<size_t>(k)];
    const double s = abscissa_[static_cast<size_t>(index)] / unit;
    t->SetNumberOfRows(2);
    t->SetValue(0, 0, s);
    t->SetValue(1, 0, s);
    t->SetValue(0, 1, y->GetMinimum());
    t->SetValue(1, 1, y->GetMaximum());
    t->Modified();
  }
  if (chartWidget_ && chartWidget_->isVisible()) chart_->render();
}

void PathInspector::listOffenders(const Results& results)
{
  if (!log_ || !logList_) return;
  listOffendingPoints(*log_, *logList_, results, kPointRole, kMaxListedPoints);
  listThermalRiskZones(*log_, *logList_, results, kPointRole, kMaxListedPoints);
}

}  // namespace spira::ui
