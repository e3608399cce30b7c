#include "spira/ui/charts/joint_chart.h"

#include <algorithm>
#include <cmath>

#include <QEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QStackedLayout>
#include <QVBoxLayout>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkAxis.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkVector.h>

#include "spira/document/kinematics_result.h"
#include "spira/ui/views/point_selection.h"

namespace spira::ui {

namespace {

// Two rows of charts: each keeps room for its axis title and labels in a dock of ~300 px.
constexpr int kRows = 2;
constexpr int kClickSlop = 4;

vtkSmartPointer<vtkTable> makeTable(const char* y)
{
  auto t = vtkSmartPointer<vtkTable>::New();
  for (const char* name : {"index", y}) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    t->AddColumn(a);
  }
  return t;
}

void styleText(vtkTextProperty* t, int size, bool bold)
{
  t->SetColor(0.13, 0.15, 0.19);
  t->SetFontSize(size);
  t->SetBold(bold);
  t->ShadowOff();
  t->SetFontFamilyToArial();
}

void setLine(vtkTable* t, double x0, double x1, double y)
{
  t->SetNumberOfRows(2);
  t->SetValue(0, 0, x0);
  t->SetValue(1, 0, x1);
  t->SetValue(0, 1, y);
  t->SetValue(1, 1, y);
  t->Modified();
}

}  // namespace

JointChart::JointChart(PointSelection* selection, QWidget* parent) : QWidget(parent), selection_(selection)
{
  setObjectName(QStringLiteral("jointChart"));
  auto* stack = new QStackedLayout(this);
  empty_ = new QLabel(tr("Set a robot cell and plan the part (F5) to chart the robot's axes along the path."),
                      this);
  empty_->setAlignment(Qt::AlignCenter);
  empty_->setWordWrap(true);
  empty_->setStyleSheet(QStringLiteral("color: palette(mid);"));
  stack->addWidget(empty_);
  page_ = new QWidget(this);
  auto* layout = new QVBoxLayout(page_);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  key_ = new QLabel(page_);
  key_->setTextFormat(Qt::RichText);
  key_->setContentsMargins(8, 2, 8, 2);
  key_->setText(
      tr("<span style='color:#1f5fa8'>&#9472;&#9472;</span> axis angle (controller degrees) "
         "&nbsp;&nbsp; <span style='color:#be2828'><b>- - -</b></span> software limits &nbsp;&nbsp; "
         "<span style='color:#ff00e6'>&#9679;</span> unreachable or colliding &nbsp;&nbsp; "
         "<span style='color:#e6a000'><b>|</b></span> selected point (click a chart to select)"));
  layout->addWidget(key_);
  widget_ = new QVTKOpenGLNativeWidget(page_);
  widget_->setRenderWindow(window_);
  widget_->installEventFilter(this);
  layout->addWidget(widget_, 1);
  stack->addWidget(page_);
  view_->SetRenderWindow(window_);
  view_->SetInteractor(widget_->interactor());
  view_->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  window_->SetMultiSamples(4);
  stack->setCurrentWidget(empty_);
  connect(selection_, &PointSelection::changed, this, [this] { updateCursor(); });
}

JointChart::~JointChart() = default;

vtkChartXY* JointChart::chart(int axis) const
{
  return charts_.at(static_cast<size_t>(axis));
}

vtkTable* JointChart::table(int axis) const
{
  return tables_.at(static_cast<size_t>(axis));
}

vtkTable* JointChart::limitTable(int axis, int which) const
{
  return (which == 0 ? lower_ : upper_).at(static_cast<size_t>(axis));
}

void JointChart::setKinematics(std::shared_ptr<const KinematicsResult> kinematics)
{
  if (kinematics == kinematics_) return;
  kinematics_ = std::move(kinematics);
  rebuild();
}

void JointChart::rebuild()
{
  auto* stack = static_cast<QStackedLayout*>(layout());
  const KinematicsResult* k = kinematics_.get();
  const size_t axes = k ? k->axes.size() : 0;
  const size_t n = k ? k->size() : 0;
  if (axes == 0 || n < 2) {
    stack->setCurrentWidget(empty_);
    return;
  }
  if (!matrix_ || charts_.size() != axes) buildCharts(axes);
  const double last = static_cast<double>(n - 1);
  for (size_t a = 0; a < axes; ++a) {
    auto [lo, hi] = fillAxis(*k, a);
    const AxisLimit& lim = k->axes[a];
    setLine(lower_[a], 0.0, last, lim.minDeg);
    setLine(upper_[a], 0.0, last, lim.maxDeg);
    frameAxis(a, lim, last, lo, hi);
  }
  stack->setCurrentWidget(page_);
  updateCursor();
}

void JointChart::buildCharts(size_t axes)
{
  if (matrix_) view_->GetScene()->RemoveItem(matrix_);
  matrix_ = vtkSmartPointer<vtkChartMatrix>::New();
  view_->GetScene()->AddItem(matrix_);
  const int rows = kRows;
  const size_t columns = (axes + kRows - 1) / kRows;
  matrix_->SetSize(vtkVector2i(static_cast<int>(columns), rows));
  matrix_->SetBorders(62, 40, 16, 8);
  matrix_->SetGutter(vtkVector2f(70.0f, 14.0f));
  charts_.clear(), tables_.clear(), lower_.clear(), upper_.clear(), flagged_.clear(), cursors_.clear();
  cursorPlots_.clear();
  for (size_t a = 0; a < axes; ++a) addAxisChart(a, axes, columns);
}

void JointChart::addAxisChart(size_t a, size_t axes, size_t columns)
{
  const int col = static_cast<int>(a % columns), row = static_cast<int>(a / columns);
  // The matrix counts rows from the bottom; A1 goes top left.
  auto* c = vtkChartXY::SafeDownCast(matrix_->GetChart(vtkVector2i(col, kRows - 1 - row)));
  c->SetShowLegend(false);
  charts_.push_back(c);
  tables_.push_back(makeTable("deg"));
  lower_.push_back(makeTable("min"));
  upper_.push_back(makeTable("max"));
  flagged_.push_back(makeTable("deg"));
  cursors_.push_back(makeTable("deg"));
  for (vtkTable* limit : {lower_.back().Get(), upper_.back().Get()}) {
    vtkPlot* l = c->AddPlot(vtkChart::LINE);
    l->SetInputData(limit, 0, 1);
    l->SetColor(190, 40, 40, 255);
    l->SetWidth(1.4f);
    l->GetPen()->SetLineType(vtkPen::DASH_LINE);
  }
  vtkPlot* curve = c->AddPlot(vtkChart::LINE);
  curve->SetInputData(tables_.back(), 0, 1);
  curve->SetColor(31, 95, 168, 255);
  curve->SetWidth(1.6f);
  auto* bad = vtkPlotPoints::SafeDownCast(c->AddPlot(vtkChart::POINTS));
  bad->SetInputData(flagged_.back(), 0, 1);
  bad->SetColor(255, 0, 230, 255);
  bad->SetMarkerStyle(vtkPlotPoints::CIRCLE);
  bad->SetMarkerSize(5.0f);
  vtkPlot* cursor = c->AddPlot(vtkChart::LINE);
  cursor->SetInputData(cursors_.back(), 0, 1);
  cursor->SetColor(230, 160, 0, 255);
  cursor->SetWidth(2.0f);
  cursor->SetVisible(false);
  cursorPlots_.push_back(cursor);
  vtkAxis* x = c->GetAxis(vtkAxis::BOTTOM);
  const bool bottomRow = a + columns >= axes;
  x->SetLabelsVisible(bottomRow);
  x->SetTitle(bottomRow ? "Point index" : "");
  styleText(x->GetTitleProperties(), 11, true);
  styleText(x->GetLabelProperties(), 10, false);
  vtkAxis* y = c->GetAxis(vtkAxis::LEFT);
  styleText(y->GetTitleProperties(), 12, true);
  styleText(y->GetLabelProperties(), 10, false);
  for (vtkAxis* ax : {x, y}) {
    ax->GetGridPen()->SetColor(225, 228, 234);
    ax->GetPen()->SetColor(120, 126, 136);
  }
}

std::pair<double, double> JointChart::fillAxis(const KinematicsResult& k, size_t a)
{
  const size_t n = k.size();
  vtkTable* t = tables_[a];
  vtkTable* f = flagged_[a];
  t->SetNumberOfRows(static_cast<vtkIdType>(n));
  f->SetNumberOfRows(0);
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (size_t i = 0; i < n; ++i) {
    const double v = axisValuesDeg(k, i).at(a);
    t->SetValue(static_cast<vtkIdType>(i), 0, static_cast<double>(i));
    t->SetValue(static_cast<vtkIdType>(i), 1, v);
    lo = std::min(lo, v), hi = std::max(hi, v);
    const bool flagged = i < k.checks.size() && (!k.checks[i].reachable || k.checks[i].collision);
    if (flagged) {
      const vtkIdType r = f->GetNumberOfRows();
      f->SetNumberOfRows(r + 1);
      f->SetValue(r, 0, static_cast<double>(i));
      f->SetValue(r, 1, v);
    }
  }
  t->Modified();
  f->Modified();
  return {lo, hi};
}

void JointChart::frameAxis(size_t a, const AxisLimit& lim, double last, double lo, double hi)
{
  vtkChartXY* c = charts_[a];
  vtkAxis* x = c->GetAxis(vtkAxis::BOTTOM);
  x->SetBehavior(vtkAxis::FIXED);
  x->SetRange(0.0, last);
  vtkAxis* y = c->GetAxis(vtkAxis::LEFT);
  y->SetTitle(lim.name + " (deg)");
  y->SetBehavior(vtkAxis::FIXED);
  // The limits frame the curve: the margin to them is what the chart is read for. Only a
  // multi-turn axis (a turntable's +/-100 turns) shows the curve's own range instead, where its
  // limits would flatten the curve into a line.
  const bool near = lim.maxDeg - lim.minDeg <= 720.0;
  const bool showMin = near, showMax = near;
  if (showMin) lo = std::min(lo, lim.minDeg);
  if (showMax) hi = std::max(hi, lim.maxDeg);
  const double pad = 0.08 * std::max(hi - lo, 1.0);
  y->SetRange(lo - pad, hi + pad);
  // Ticks at the limits shown and at zero (or the middle) read at a glance on short charts.
  vtkNew<vtkDoubleArray> ticks;
  vtkNew<vtkStringArray> labels;
  std::vector<double> at;
  if (showMin) at.push_back(lim.minDeg);
  const double mid = lo < 0.0 && hi > 0.0 ? 0.0 : 0.5 * (lo + hi);
  at.push_back(mid);
  if (showMax) at.push_back(lim.maxDeg);
  if (!showMin && !showMax) at = {lo, mid, hi};
  const int decimals = hi - lo < 10.0 ? 1 : 0;
  for (double v : at) {
    ticks->InsertNextValue(v);
    labels->InsertNextValue(QString::number(v, 'f', decimals).toStdString());
  }
  y->SetCustomTickPositions(ticks, labels);
  for (vtkIdType p = 0; p < c->GetNumberOfPlots(); ++p) c->GetPlot(p)->GetInput()->Modified();
}

void JointChart::updateCursor()
{
  const long long i = selection_->index();
  const bool on = kinematics_ && i >= 0 && i < static_cast<long long>(kinematics_->size());
  cursor_ = on ? i : -1;
  for (size_t a = 0; a < charts_.size(); ++a) {
    cursorPlots_[a]->SetVisible(on && kinematics_ != nullptr);
    if (!on) continue;
    vtkAxis* y = charts_[a]->GetAxis(vtkAxis::LEFT);
    vtkTable* t = cursors_[a];
    t->SetNumberOfRows(2);
    t->SetValue(0, 0, static_cast<double>(i));
    t->SetValue(1, 0, static_cast<double>(i));
    t->SetValue(0, 1, y->GetMinimum());
    t->SetValue(1, 1, y->GetMaximum());
    t->Modified();
  }
  if (widget_->isVisible()) render();
}

long long JointChart::indexAt(const QPoint& pos) const
{
  if (!kinematics_ || charts_.empty()) return -1;
  const double dpr = widget_->devicePixelRatioF();
  const double sx = pos.x() * dpr, sy = (widget_->height() - pos.y()) * dpr;
  for (vtkChartXY* c : charts_) {
    vtkAxis* x = c->GetAxis(vtkAxis::BOTTOM);
    vtkAxis* y = c->GetAxis(vtkAxis::LEFT);
    const float *x1 = x->GetPoint1(), *x2 = x->GetPoint2(), *y1 = y->GetPoint1(), *y2 = y->GetPoint2();
    if (sx < x1[0] || sx > x2[0] || sy < std::min(y1[1], y2[1]) || sy > std::max(y1[1], y2[1])) continue;
    const double v = x->GetMinimum() + (sx - x1[0]) / (x2[0] - x1[0]) * (x->GetMaximum() - x->GetMinimum());
    return std::clamp<long long>(std::llround(v), 0, static_cast<long long>(kinematics_->size()) - 1);
  }
  return -1;
}

QPoint JointChart::positionOf(int axis, long long i) const
{
  vtkChartXY* c = chart(axis);
  vtkAxis* x = c->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* y = c->GetAxis(vtkAxis::LEFT);
  const double v = table(axis)->GetValue(static_cast<vtkIdType>(i), 1).ToDouble();
  const double sx = x->GetPoint1()[0] + (static_cast<double>(i) - x->GetMinimum()) /
                                            (x->GetMaximum() - x->GetMinimum()) *
                                            (x->GetPoint2()[0] - x->GetPoint1()[0]);
  const double sy = y->GetPoint1()[1] + (v - y->GetMinimum()) / (y->GetMaximum() - y->GetMinimum()) *
                                            (y->GetPoint2()[1] - y->GetPoint1()[1]);
  const double dpr = widget_->devicePixelRatioF();
  return QPoint(static_cast<int>(std::lround(sx / dpr)),
                static_cast<int>(std::lround(widget_->height() - sy / dpr)));
}

bool JointChart::eventFilter(QObject* watched, QEvent* event)
{
  if (watched == widget_) {
    if (event->type() == QEvent::MouseButtonPress) {
      auto* m = static_cast<QMouseEvent*>(event);
      if (m->button() == Qt::LeftButton) press_ = m->pos();
    } else if (event->type() == QEvent::MouseButtonRelease) {
      auto* m = static_cast<QMouseEvent*>(event);
      if (m->button() == Qt::LeftButton && (m->pos() - press_).manhattanLength() <= kClickSlop) {
        const long long i = indexAt(m->pos());
        if (i >= 0) selection_->select(i);
      }
    }
  }
  return QWidget::eventFilter(watched, event);
}

void JointChart::render()
{
  if (widget_->isValid()) view_->Render();
}

QImage JointChart::grabImage()
{
  render();
  return widget_->grabFramebuffer();
}

}  // namespace spira::ui
