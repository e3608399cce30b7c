#include "spira/ui/charts/probe_chart.h"

#include <algorithm>
#include <cmath>

#include <QLabel>
#include <QLocale>
#include <QStackedLayout>
#include <QVBoxLayout>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include "spira/document/thermal_result.h"

namespace spira::ui {

namespace {

void makeColumns(vtkTable* t)
{
  for (const char* name : {"t", "temperature"}) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    t->AddColumn(a);
  }
}

void setRows(vtkTable* t, const std::vector<std::array<double, 2>>& rows)
{
  t->SetNumberOfRows(static_cast<vtkIdType>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i) {
    t->SetValue(static_cast<vtkIdType>(i), 0, rows[i][0]);
    t->SetValue(static_cast<vtkIdType>(i), 1, rows[i][1]);
  }
  t->Modified();
}

void styleAxis(vtkAxis* a, const std::string& title)
{
  a->SetTitle(title);
  for (vtkTextProperty* t : {a->GetTitleProperties(), a->GetLabelProperties()}) {
    t->SetColor(0.13, 0.15, 0.19);
    t->ShadowOff();
    t->SetFontFamilyToArial();
  }
  a->GetTitleProperties()->SetFontSize(12);
  a->GetTitleProperties()->SetBold(true);
  a->GetLabelProperties()->SetFontSize(11);
  a->GetGridPen()->SetColor(220, 224, 230);
  a->GetPen()->SetColor(120, 126, 136);
}

vtkPlot* addLine(vtkChartXY* chart, vtkTable* table, unsigned char r, unsigned char g, unsigned char b,
                 float width, int lineType)
{
  vtkPlot* line = chart->AddPlot(vtkChart::LINE);
  line->SetInputData(table, 0, 1);
  line->SetColor(r, g, b, 255);
  line->SetWidth(width);
  line->GetPen()->SetLineType(lineType);
  return line;
}

}  // namespace

ProbeChart::ProbeChart(QWidget* parent) : QWidget(parent)
{
  setObjectName(QStringLiteral("probeChart"));
  auto* stack = new QStackedLayout(this);
  empty_ = new QLabel(this);
  empty_->setAlignment(Qt::AlignCenter);
  empty_->setWordWrap(true);
  empty_->setStyleSheet(QStringLiteral("color: palette(mid);"));
  stack->addWidget(empty_);
  page_ = new QWidget(this);
  auto* layout = new QVBoxLayout(page_);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  key_ = new QLabel(page_);
  key_->setObjectName(QStringLiteral("probeKey"));
  key_->setTextFormat(Qt::RichText);
  key_->setContentsMargins(8, 2, 8, 2);
  key_->setWordWrap(true);
  layout->addWidget(key_);
  widget_ = new QVTKOpenGLNativeWidget(page_);
  widget_->setRenderWindow(window_);
  layout->addWidget(widget_, 1);
  stack->addWidget(page_);
  view_->SetRenderWindow(window_);
  view_->SetInteractor(widget_->interactor());
  view_->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  window_->SetMultiSamples(4);

  vtkNew<vtkChartXY> chart;
  chart_ = chart;
  view_->GetScene()->AddItem(chart);
  chart_->SetShowLegend(false);
  for (vtkTable* t : {history_.Get(), melting_.Get(), limit_.Get(), cursor_.Get(), peakMark_.Get()})
    makeColumns(t);
  plots_[0] = addLine(chart_, history_, 200, 60, 20, 1.8f, vtkPen::SOLID_LINE);
  plots_[1] = addLine(chart_, melting_, 190, 40, 40, 1.4f, vtkPen::DASH_LINE);
  plots_[2] = addLine(chart_, limit_, 31, 95, 168, 1.4f, vtkPen::DASH_LINE);
  plots_[3] = addLine(chart_, cursor_, 90, 96, 110, 1.2f, vtkPen::DASH_DOT_LINE);
  auto* peak = vtkPlotPoints::SafeDownCast(chart_->AddPlot(vtkChart::POINTS));
  peak->SetInputData(peakMark_, 0, 1);
  peak->SetColor(200, 60, 20, 255);
  peak->SetMarkerStyle(vtkPlotPoints::DIAMOND);
  peak->SetMarkerSize(10.0f);
  plots_[4] = peak;
  styleAxis(chart_->GetAxis(vtkAxis::LEFT), "T (°C)");
  styleAxis(chart_->GetAxis(vtkAxis::BOTTOM), "t (s)");
  update();
}

ProbeChart::~ProbeChart() = default;

void ProbeChart::setResult(std::shared_ptr<const ThermalStageResult> result, double meltingC,
                           double interpassLimitC)
{
  result_ = result && !result->frames.empty() ? std::move(result) : nullptr;
  meltingC_ = meltingC;
  limitC_ = interpassLimitC;
  minutes_ = result_ && result_->frames.times.back() > 600.0;
  if (result_ && point_ >= static_cast<long long>(result_->pointCount())) point_ = -1;
  update();
}

void ProbeChart::setPoint(long long index, double arrival)
{
  point_ = index;
  arrival_ = arrival;
  update();
}

void ProbeChart::setCursorTime(double t)
{
  cursorT_ = t;
  update();
}

QString ProbeChart::title() const
{
  return key_->text();
}

void ProbeChart::update()
{
  auto* stack = static_cast<QStackedLayout*>(layout());
  const bool hasPoint = result_ && point_ >= 0 && point_ < static_cast<long long>(result_->pointCount());
  if (!hasPoint) {
    empty_->setText(result_
                        ? tr("Click a point of the path (or a risk message) to chart its temperature.")
                        : tr("Enable the thermal stage (Plan > Thermal) and plan to chart temperatures."));
    for (vtkTable* t : {history_.Get(), melting_.Get(), limit_.Get(), cursor_.Get(), peakMark_.Get()})
      setRows(t, {});
    stack->setCurrentWidget(empty_);
    return;
  }
  const double scale = minutes_ ? 1.0 / 60.0 : 1.0;
  const auto i = static_cast<size_t>(point_);
  std::vector<std::array<double, 2>> rows = result_->historyAt(static_cast<size_t>(result_->pointNode[i]));
  for (auto& r : rows) r[0] *= scale;
  setRows(history_, rows);
  const double t0 = result_->frames.times.front() * scale, t1 = result_->frames.times.back() * scale;
  setRows(melting_, {{t0, meltingC_}, {t1, meltingC_}});
  setRows(limit_, limitC_ > 0.0 ? std::vector<std::array<double, 2>>{{t0, limitC_}, {t1, limitC_}}
                                : std::vector<std::array<double, 2>>{});
  // The scale holds the history, melting and the limit; the node's own peak under the point source
  // is far above them and is drawn at the top edge, its value in the key.
  double hi = std::max(meltingC_, limitC_);
  for (const auto& r : rows) hi = std::max(hi, r[1]);
  hi *= 1.15;
  double lo = 0.0;
  for (const auto& r : rows) lo = std::min(lo, r[1]);
  setRows(peakMark_, arrival_ >= 0.0 ? std::vector<std::array<double, 2>>{{arrival_ * scale,
                                                                           std::min(result_->peak[i], hi)}}
                                     : std::vector<std::array<double, 2>>{});
  setRows(cursor_, cursorT_ >= 0.0
                       ? std::vector<std::array<double, 2>>{{cursorT_ * scale, lo}, {cursorT_ * scale, hi}}
                       : std::vector<std::array<double, 2>>{});
  vtkAxis* y = chart_->GetAxis(vtkAxis::LEFT);
  y->SetBehavior(vtkAxis::FIXED);
  y->SetRange(lo, hi);
  // From a little before the torch lays the point (nothing is there earlier) to the end.
  const double born = arrival_ >= 0.0 ? arrival_ * scale : (rows.empty() ? t0 : rows.front()[0]);
  const double from = std::max(t0, born - 0.05 * (t1 - t0));
  vtkAxis* x = chart_->GetAxis(vtkAxis::BOTTOM);
  x->SetBehavior(vtkAxis::FIXED);
  x->SetRange(from, std::max(t1, from + 1e-6));
  x->SetTitle(minutes_ ? "t (min)" : "t (s)");
  // A line of fewer than two points is not drawn (VTK complains); the peak is one point.
  for (size_t k = 0; k < 4; ++k) plots_[k]->SetVisible(plots_[k]->GetInput()->GetNumberOfRows() >= 2);
  plots_[4]->SetVisible(peakMark_->GetNumberOfRows() > 0);
  const QLocale loc;
  const double interpass = result_->interpass[i];
  key_->setText(
      tr("<b>Point %1</b>: peak %2 °C, interpass %3 &nbsp;&nbsp; "
         "<span style='color:#c83c14'>&#9472;&#9472;</span> temperature (frames) &nbsp; "
         "<span style='color:#c83c14'>&#9670;</span> peak as the torch passes &nbsp; "
         "<span style='color:#be2828'><b>- - -</b></span> melting %4 °C%5")
          .arg(loc.toString(point_))
          .arg(loc.toString(result_->peak[i], 'f', 0))
          .arg(std::isfinite(interpass) ? loc.toString(interpass, 'f', 0) + QStringLiteral(" °C")
                                        : tr("none"))
          .arg(loc.toString(meltingC_, 'f', 0))
          .arg(limitC_ > 0.0
                   ? tr(" &nbsp; <span style='color:#1f5fa8'><b>- - -</b></span> interpass limit %1 °C")
                         .arg(loc.toString(limitC_, 'f', 0))
                   : QString()));
  stack->setCurrentWidget(page_);
  render();
}

void ProbeChart::render()
{
  if (widget_->isValid()) view_->Render();
}

QImage ProbeChart::grabImage()
{
  render();
  return widget_->grabFramebuffer();
}

}  // namespace spira::ui
