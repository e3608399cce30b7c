#pragma once

#include <vector>

#include <QString>

#include <vtkSmartPointer.h>

class vtkLookupTable;
class vtkRenderer;
class vtkScalarBarActor;
class vtkTextActor;

namespace spira::ui {

enum class ColorMap {
  Viridis,  // sequential, perceptually uniform: fields, revolutions
  Plasma,   // sequential: speeds
  // Diverging around the middle of the range through a mid-tone green (not white, which would
  // vanish on the light background): deposit heights, thin blue, nominal green, thick red.
  Window,
  Inferno,  // sequential, dark to bright yellow: temperatures
  Risk,     // two colours, safe green at 0 and collapse-risk red at 1
};

// A 256-entry table of `map` over [lo, hi]; values outside take the end colours.
vtkSmartPointer<vtkLookupTable> makeLookupTable(ColorMap map, double lo, double hi);

// A vertical colour legend in Spira's style: the colour bar with its labels and, above it, a
// title aligned with the bar's outer edge (so a long title runs into the view, never off it).
class ColorLegend {
 public:
  enum class Side { Left, Right };
  ColorLegend(vtkRenderer* renderer, Side side);
  ~ColorLegend();

  void setLookupTable(vtkLookupTable* table);
  void setTitle(const QString& title);
  QString title() const { return title_; }
  void setLabelFormat(const QString& format);
  // Labels at these values only (empty: evenly spaced labels).
  void setLabels(const std::vector<double>& values);
  void setVisible(bool on);
  bool visible() const;
  vtkScalarBarActor* bar() const;

 private:
  QString title_;
  vtkSmartPointer<vtkScalarBarActor> bar_;
  vtkSmartPointer<vtkTextActor> text_;
};

// printf format for legend labels of a range: enough decimals to tell the labels apart.
QString labelFormatFor(double lo, double hi);

}  // namespace spira::ui
