#include "spira/ui/charts/process_chart.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <QLabel>
#include <QStackedLayout>
#include <QVBoxLayout>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkAutoInit.h>
#include <vtkAxis.h>
#include <vtkBrush.h>
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

#include "spira/base/units.h"
#include "spira/path/trajectory.h"

// The 2D charts draw through the OpenGL context device, registered here like the 3D view's.
VTK_MODULE_INIT(vtkRenderingContextOpenGL2);

namespace spira::ui {

namespace {

void makeColumns(vtkTable* t, const char* x, const char* y)
{
  for (const char* name : {x, y}) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    t->AddColumn(a);
  }
}

void styleText(vtkTextProperty* t, int size, bool bold)
{
  t->SetColor(0.13, 0.15, 0.19);
  t->SetFontSize(size);
  t->SetBold(bold);
  t->ShadowOff();
  t->SetFontFamilyToArial();
}

void styleAxis(vtkAxis* a, const char* title)
{
  a->SetTitle(title);
  styleText(a->GetTitleProperties(), 12, true);
  styleText(a->GetLabelProperties(), 11, false);
  a->GetGridPen()->SetColor(220, 224, 230);
  a->GetPen()->SetColor(120, 126, 136);
}

// A fixed axis range around [lo, hi] with a little air, never empty, and ticks at `ticks` only:
// rows this short have room for three labels.
void setAxis(vtkAxis* a, double lo, double hi, std::vector<double> ticks)
{
  if (!(hi > lo)) {
    const double pad = std::max(1e-3, 0.05 * std::abs(lo));
    lo -= pad, hi += pad;
  }
  const double pad = 0.12 * (hi - lo);
  a->SetBehavior(vtkAxis::FIXED);
  a->SetRange(lo - pad, hi + pad);
  vtkNew<vtkDoubleArray> positions;
  for (double t : ticks) positions->InsertNextValue(t);
  vtkNew<vtkStringArray> labels;
  const double span = std::max(std::abs(hi - lo), 1e-9);
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(span / 2.0))) + 1, 0, 3);
  for (double t : ticks) labels->InsertNextValue(QString::number(t, 'f', decimals).toStdString());
  a->SetCustomTickPositions(positions, labels);
}

}  // namespace

ProcessChart::ProcessChart(QWidget* parent) : QWidget(parent)
{
  setObjectName(QStringLiteral("processChart"));
  auto* stack = new QStackedLayout(this);
  empty_ =
      new QLabel(tr("Plan the part (F5) to chart its deposit height, travel speed and wire feed."), this);
  empty_->setAlignment(Qt::AlignCenter);
  empty_->setStyleSheet(QStringLiteral("color: palette(mid);"));
  stack->addWidget(empty_);
  auto* page = new QWidget(this);
  auto* pageLayout = new QVBoxLayout(page);
  pageLayout->setContentsMargins(0, 0, 0, 0);
  pageLayout->setSpacing(0);
  // The key in Qt rather than VTK's legend box, which would cover the end of the curves.
  key_ = new QLabel(page);
  key_->setObjectName(QStringLiteral("chartKey"));
  key_->setTextFormat(Qt::RichText);
  key_->setContentsMargins(8, 2, 8, 2);
  key_->setText(
      tr("<span style='color:#1f5fa8'>&#9472;&#9472;</span> deposit height h &nbsp;&nbsp; "
         "<span style='color:#c8641e'>&#9472;&#9472;</span> travel speed TS &nbsp;&nbsp; "
         "<span style='color:#2a8a3e'>&#9472;&#9472;</span> wire-feed speed WFS &nbsp;&nbsp; "
         "<span style='color:#be2828'><b>- - -</b></span> process window h_min, h_max &nbsp;&nbsp; "
         "<span style='color:#ff00e6'>&#9679;</span> outside the window &nbsp;&nbsp; "
         "<span style='color:#5a606e'><b>-&middot;-</b></span> end of the build shown"));
  pageLayout->addWidget(key_);
  widget_ = new QVTKOpenGLNativeWidget(page);
  widget_->setRenderWindow(window_);
  pageLayout->addWidget(widget_, 1);
  page_ = page;
  stack->addWidget(page);
  view_->SetRenderWindow(window_);
  view_->SetInteractor(widget_->interactor());
  view_->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  window_->SetMultiSamples(4);

  matrix_->SetSize(vtkVector2i(1, kPanels));
  matrix_->SetBorders(64, 42, 70, 8);
  matrix_->SetGutter(vtkVector2f(20.0f, 12.0f));
  view_->GetScene()->AddItem(matrix_);
  for (int k = 0; k < kPanels; ++k) {
    // The matrix counts panels from the bottom; the height panel goes on top.
    auto* chart = vtkChartXY::SafeDownCast(matrix_->GetChart(vtkVector2i(0, kPanels - 1 - k)));
    panels_[static_cast<size_t>(k)] = chart;
    chart->SetShowLegend(false);
    styleAxis(chart->GetAxis(vtkAxis::BOTTOM), "");
    chart->GetAxis(vtkAxis::BOTTOM)->SetLabelsVisible(k == kPanels - 1);
    makeColumns(cursors_[static_cast<size_t>(k)], "s", "value");
    vtkPlot* cursor = chart->AddPlot(vtkChart::LINE);
    cursor->SetInputData(cursors_[static_cast<size_t>(k)], 0, 1);
    cursor->SetColor(90, 96, 110, 200);
    cursor->SetWidth(1.2);
    cursor->GetPen()->SetLineType(vtkPen::DASH_DOT_LINE);
    cursor->SetVisible(false);
    cursorPlots_[static_cast<size_t>(k)] = cursor;
  }

  // Height alone on top; travel speed (left axis) and wire feed (right axis) share the bottom
  // panel: in synergic mode one of them is constant, in constant-TS mode the other.
  const char* titles[kRows] = {"h (mm)", "TS (mm/s)", "WFS (m/min)"};
  const unsigned char colours[kRows][3] = {{31, 95, 168}, {200, 100, 30}, {42, 138, 62}};
  for (int r = 0; r < kRows; ++r) {
    vtkChartXY* chart = this->chart(static_cast<Row>(r));
    makeColumns(tables_[static_cast<size_t>(r)], "s", "value");
    vtkPlot* line = chart->AddPlot(vtkChart::LINE);
    line->SetInputData(tables_[static_cast<size_t>(r)], 0, 1);
    line->SetColor(colours[r][0], colours[r][1], colours[r][2], 255);
    line->SetWidth(1.6);
    line->SetLabel(titles[r]);
    const int corner = r == WireFeedRow ? 1 : 0;  // 1: bottom and right axes
    chart->SetPlotCorner(line, corner);
    vtkAxis* y = chart->GetAxis(corner == 1 ? vtkAxis::RIGHT : vtkAxis::LEFT);
    styleAxis(y, titles[r]);
    y->GetTitleProperties()->SetColor(colours[r][0] / 255.0, colours[r][1] / 255.0, colours[r][2] / 255.0);
  }
  vtkChartXY* height = chart(HeightRow);
  const char* names[2] = {"h_min", "h_max"};
  for (int i = 0; i < 2; ++i) {
    makeColumns(windowLines_[static_cast<size_t>(i)], "s", names[i]);
    vtkPlot* limit = height->AddPlot(vtkChart::LINE);
    limit->SetInputData(windowLines_[static_cast<size_t>(i)], 0, 1);
    limit->SetColor(190, 40, 40, 255);
    limit->SetWidth(1.4);
    limit->GetPen()->SetLineType(vtkPen::DASH_LINE);
    limit->SetLabel(names[i]);
  }
  makeColumns(violations_, "s", "height");
  auto* outside = vtkPlotPoints::SafeDownCast(height->AddPlot(vtkChart::POINTS));
  outside->SetInputData(violations_, 0, 1);
  outside->SetColor(255, 0, 230, 255);
  outside->SetMarkerStyle(vtkPlotPoints::CIRCLE);
  outside->SetMarkerSize(6.0f);
  outside->SetLabel("outside the window");
  stack->setCurrentWidget(empty_);
}

ProcessChart::~ProcessChart() = default;

vtkChartXY* ProcessChart::chart(Row row) const
{
  return panels_.at(row == HeightRow ? 0 : 1);
}

vtkTable* ProcessChart::table(Row row) const
{
  return tables_.at(static_cast<size_t>(row));
}

vtkTable* ProcessChart::windowTable(int which) const
{
  return windowLines_.at(static_cast<size_t>(which));
}

void ProcessChart::setPath(const Trajectory* path, bool hasSpeeds, std::optional<PlanWindow> window)
{
  auto* stack = static_cast<QStackedLayout*>(layout());
  const size_t n = path ? path->size() : 0;
  for (auto& t : tables_) t->SetNumberOfRows(0);
  for (auto& t : windowLines_) t->SetNumberOfRows(0);
  violations_->SetNumberOfRows(0);
  if (n < 2) {
    length_ = 0.0;
    stack->setCurrentWidget(empty_);
    return;
  }
  length_ = path->length();
  metres_ = length_ > 5000.0;
  const double unit = metres_ ? 1000.0 : 1.0;
  const double toMetresPerMinute = 1.0 / toInternalFactor("m/min");
  const vtkIdType rows = static_cast<vtkIdType>(n);
  for (auto& t : tables_) t->SetNumberOfRows(hasSpeeds || &t == &tables_[HeightRow] ? rows : 0);
  double s = 0.0;
  std::array<double, kRows> lo, hi;
  lo.fill(HUGE_VAL), hi.fill(-HUGE_VAL);
  for (size_t i = 0; i < n; ++i) {
    const TrajectoryPoint& p = path->points[i];
    if (i > 0) s += (p.position - path->points[i - 1].position).norm();
    const double x = s / unit;
    const double values[kRows] = {p.height, p.travelSpeed, p.wireFeed * toMetresPerMinute};
    for (int r = 0; r < kRows; ++r) {
      if (r != HeightRow && !hasSpeeds) continue;
      vtkTable* t = tables_[static_cast<size_t>(r)];
      t->SetValue(static_cast<vtkIdType>(i), 0, x);
      t->SetValue(static_cast<vtkIdType>(i), 1, values[r]);
      lo[static_cast<size_t>(r)] = std::min(lo[static_cast<size_t>(r)], values[r]);
      hi[static_cast<size_t>(r)] = std::max(hi[static_cast<size_t>(r)], values[r]);
    }
    if (window && window->outside(p.height)) {
      const vtkIdType k = violations_->GetNumberOfRows();
      violations_->SetNumberOfRows(k + 1);
      violations_->SetValue(k, 0, x);
      violations_->SetValue(k, 1, p.height);
    }
  }
  if (window) {
    const double limits[2] = {window->hMin, window->hMax};
    for (int i = 0; i < 2; ++i) {
      vtkTable* t = windowLines_[static_cast<size_t>(i)];
      t->SetNumberOfRows(2);
      t->SetValue(0, 0, 0.0);
      t->SetValue(1, 0, length_ / unit);
      t->SetValue(0, 1, limits[i]);
      t->SetValue(1, 1, limits[i]);
    }
    // The window frames the height chart even where the heights stay well inside it; the
    // extremes (a seam ramp near a closure point) stay visible around it.
    lo[HeightRow] = std::min(lo[HeightRow], window->hMin - 0.25 * (window->hMax - window->hMin));
    hi[HeightRow] = std::max(hi[HeightRow], window->hMax + 0.25 * (window->hMax - window->hMin));
  }
  for (int k = 0; k < kPanels; ++k) {
    vtkChartXY* c = panels_[static_cast<size_t>(k)];
    vtkAxis* x = c->GetAxis(vtkAxis::BOTTOM);
    x->SetBehavior(vtkAxis::FIXED);
    x->SetRange(0.0, length_ / unit);
    if (k == kPanels - 1)
      x->SetTitle(metres_ ? "Curvilinear abscissa along the path (m)"
                          : "Curvilinear abscissa along the path (mm)");
    for (vtkIdType p = 0; p < c->GetNumberOfPlots(); ++p) c->GetPlot(p)->GetInput()->Modified();
  }
  for (int r = 0; r < kRows; ++r) {
    vtkAxis* y = chart(static_cast<Row>(r))->GetAxis(r == WireFeedRow ? vtkAxis::RIGHT : vtkAxis::LEFT);
    const double a = lo[static_cast<size_t>(r)], b = hi[static_cast<size_t>(r)];
    if (r == HeightRow && window)
      setAxis(y, a, b, {window->hMin, window->h, window->hMax});
    else if (a < b)
      setAxis(y, a, b, {a, 0.5 * (a + b), b});
    else if (a == b)
      setAxis(y, a, b, {a});
  }
  stack->setCurrentWidget(page_);
  setCursor(-1.0);
}

void ProcessChart::setCursor(double s)
{
  const double unit = metres_ ? 1000.0 : 1.0;
  for (int k = 0; k < kPanels; ++k) {
    vtkPlot* cursor = cursorPlots_[static_cast<size_t>(k)];
    const bool on = s >= 0.0 && length_ > 0.0 && s < length_ * (1.0 - 1e-9);
    cursor->SetVisible(on);
    if (!on) continue;
    vtkAxis* y = panels_[static_cast<size_t>(k)]->GetAxis(vtkAxis::LEFT);
    vtkTable* t = cursors_[static_cast<size_t>(k)];
    t->SetNumberOfRows(2);
    t->SetValue(0, 0, s / unit);
    t->SetValue(1, 0, s / unit);
    t->SetValue(0, 1, y->GetMinimum());
    t->SetValue(1, 1, y->GetMaximum());
    t->Modified();
  }
  if (widget_->isVisible()) widget_->renderWindow()->Render();
}

void ProcessChart::render()
{
  if (widget_->isValid()) view_->Render();
}

QImage ProcessChart::grabImage()
{
  render();
  return widget_->grabFramebuffer();
}

}  // namespace spira::ui
