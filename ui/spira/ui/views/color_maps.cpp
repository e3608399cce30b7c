#include "spira/ui/views/color_maps.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <vtkColorTransferFunction.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace spira::ui {

namespace {

struct Stop {
  double t, r, g, b;
};

// Control points sampled from matplotlib's viridis and plasma, and Moreland's cool-warm.
constexpr std::array<Stop, 9> kViridis{{{0.000, 0.267, 0.005, 0.329},
                                        {0.125, 0.283, 0.141, 0.458},
                                        {0.250, 0.254, 0.265, 0.530},
                                        {0.375, 0.207, 0.372, 0.553},
                                        {0.500, 0.164, 0.471, 0.558},
                                        {0.625, 0.128, 0.567, 0.551},
                                        {0.750, 0.135, 0.659, 0.518},
                                        {0.875, 0.478, 0.821, 0.318},
                                        {1.000, 0.993, 0.906, 0.144}}};
constexpr std::array<Stop, 9> kPlasma{{{0.000, 0.050, 0.030, 0.528},
                                       {0.125, 0.295, 0.012, 0.615},
                                       {0.250, 0.493, 0.012, 0.658},
                                       {0.375, 0.665, 0.139, 0.586},
                                       {0.500, 0.798, 0.280, 0.470},
                                       {0.625, 0.902, 0.412, 0.360},
                                       {0.750, 0.973, 0.560, 0.254},
                                       {0.875, 0.993, 0.730, 0.155},
                                       {1.000, 0.940, 0.975, 0.131}}};
constexpr std::array<Stop, 5> kWindow{{{0.000, 0.150, 0.300, 0.820},
                                       {0.250, 0.150, 0.560, 0.800},
                                       {0.500, 0.180, 0.620, 0.330},
                                       {0.750, 0.900, 0.560, 0.120},
                                       {1.000, 0.820, 0.120, 0.120}}};

constexpr std::array<Stop, 9> kInferno{{{0.000, 0.001, 0.000, 0.014},
                                        {0.125, 0.113, 0.044, 0.266},
                                        {0.250, 0.258, 0.039, 0.406},
                                        {0.375, 0.417, 0.090, 0.433},
                                        {0.500, 0.578, 0.148, 0.404},
                                        {0.625, 0.736, 0.216, 0.330},
                                        {0.750, 0.865, 0.317, 0.226},
                                        {0.875, 0.955, 0.480, 0.096},
                                        {1.000, 0.988, 0.998, 0.645}}};
constexpr std::array<Stop, 4> kRisk{{{0.000, 0.180, 0.620, 0.330},
                                     {0.499, 0.180, 0.620, 0.330},
                                     {0.501, 0.880, 0.100, 0.100},
                                     {1.000, 0.880, 0.100, 0.100}}};

template <size_t N>
void fill(vtkColorTransferFunction* f, const std::array<Stop, N>& stops)
{
  for (const Stop& s : stops) f->AddRGBPoint(s.t, s.r, s.g, s.b);
}

}  // namespace

vtkSmartPointer<vtkLookupTable> makeLookupTable(ColorMap map, double lo, double hi)
{
  vtkNew<vtkColorTransferFunction> f;
  f->SetColorSpaceToLab();
  switch (map) {
    case ColorMap::Viridis:
      fill(f.Get(), kViridis);
      break;
    case ColorMap::Plasma:
      fill(f.Get(), kPlasma);
      break;
    case ColorMap::Window:
      fill(f.Get(), kWindow);
      break;
    case ColorMap::Inferno:
      fill(f.Get(), kInferno);
      break;
    case ColorMap::Risk:
      fill(f.Get(), kRisk);
      break;
  }
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  constexpr int n = 256;
  table->SetNumberOfTableValues(n);
  for (int i = 0; i < n; ++i) {
    double rgb[3];
    f->GetColor(static_cast<double>(i) / (n - 1), rgb);
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  if (!(hi > lo)) hi = lo + 1.0;
  table->SetTableRange(lo, hi);
  return table;
}

namespace {

void styleText(vtkTextProperty* t, int size, bool bold)
{
  t->SetColor(0.13, 0.15, 0.19);
  t->ShadowOff();
  t->ItalicOff();
  t->SetFontFamilyToArial();
  t->SetFontSize(size);
  t->SetBold(bold);
}

}  // namespace

ColorLegend::ColorLegend(vtkRenderer* renderer, Side side)
    : bar_(vtkSmartPointer<vtkScalarBarActor>::New()), text_(vtkSmartPointer<vtkTextActor>::New())
{
  const bool left = side == Side::Left;
  bar_->SetOrientationToVertical();
  bar_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  // Labels sit inside the view: right of a bar on the left, left of a bar on the right.
  bar_->SetPosition(left ? 0.015 : 0.89, 0.18);
  bar_->SetWidth(0.10);
  bar_->SetHeight(0.58);
  bar_->SetMaximumWidthInPixels(90);
  bar_->SetNumberOfLabels(5);
  bar_->SetBarRatio(0.3);
  if (left)
    bar_->SetTextPositionToSucceedScalarBar();
  else
    bar_->SetTextPositionToPrecedeScalarBar();
  bar_->UnconstrainedFontSizeOn();
  bar_->SetTitle("");
  styleText(bar_->GetLabelTextProperty(), 13, false);
  styleText(bar_->GetTitleTextProperty(), 1, false);
  bar_->DrawFrameOff();
  bar_->DrawBackgroundOff();
  bar_->VisibilityOff();
  renderer->AddViewProp(bar_);

  styleText(text_->GetTextProperty(), 14, true);
  text_->GetTextProperty()->SetJustification(left ? VTK_TEXT_LEFT : VTK_TEXT_RIGHT);
  text_->GetTextProperty()->SetVerticalJustificationToBottom();
  text_->GetTextProperty()->SetLineSpacing(1.15);
  text_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  text_->SetPosition(left ? 0.02 : 0.98, 0.78);
  text_->VisibilityOff();
  renderer->AddViewProp(text_);
}

ColorLegend::~ColorLegend() = default;

void ColorLegend::setLookupTable(vtkLookupTable* table)
{
  bar_->SetLookupTable(table);
}

void ColorLegend::setTitle(const QString& title)
{
  title_ = title;
  text_->SetInput(title.toUtf8().constData());
}

void ColorLegend::setLabelFormat(const QString& format)
{
  bar_->SetLabelFormat(format.toUtf8().constData());
}

void ColorLegend::setLabels(const std::vector<double>& values)
{
  if (values.empty()) {
    bar_->UseCustomLabelsOff();
    return;
  }
  vtkNew<vtkDoubleArray> labels;
  for (double v : values) labels->InsertNextValue(v);
  bar_->SetCustomLabels(labels);
  bar_->UseCustomLabelsOn();
}

void ColorLegend::setVisible(bool on)
{
  bar_->SetVisibility(on);
  text_->SetVisibility(on);
}

vtkScalarBarActor* ColorLegend::bar() const
{
  return bar_;
}

bool ColorLegend::visible() const
{
  return bar_->GetVisibility() != 0;
}

QString labelFormatFor(double lo, double hi)
{
  const double span = std::abs(hi - lo);
  if (!(span > 0.0)) return QStringLiteral("%.2f");
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(span / 4.0))) + 1, 0, 4);
  return QStringLiteral("%.%1f").arg(decimals);
}

}  // namespace spira::ui
