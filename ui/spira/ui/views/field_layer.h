#pragma once

#include <utility>
#include <vector>

#include <QString>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "spira/ui/views/color_maps.h"

class vtkActor;
class vtkContourFilter;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;

namespace spira::ui {

// The scalar field of a plan drawn on the part: the part's surface coloured by it, iso-lines at
// a round spacing, and a legend with the field's name and unit. The colour range can be narrowed
// to look at part of the field.
class FieldLayer {
 public:
  FieldLayer(vtkRenderer* renderer, vtkPolyDataMapper* partMapper);
  ~FieldLayer();

  // The part's shaded surface (from toShadedPolyData); the field is mapped onto it again.
  void setSurface(vtkPolyData* surface);
  // One value per mesh vertex, or empty to clear; `name` and `unit` title the legend.
  void setField(const std::vector<double>& values, const QString& name, const QString& unit);
  bool hasField() const { return !values_.empty(); }
  // Colours the part (and draws iso-lines and the legend) or leaves it plain.
  void setVisible(bool on);
  bool visible() const { return visible_; }

  std::pair<double, double> dataRange() const { return dataRange_; }
  std::pair<double, double> range() const { return range_; }
  void setRange(double lo, double hi);
  // About `count` iso-lines at a round spacing over the colour range; 0 draws none.
  void setIsoLineCount(int count);
  int isoLineCount() const { return isoCount_; }
  double isoSpacing() const { return isoSpacing_; }

  const ColorLegend& legend() const { return legend_; }
  // The iso-lines as drawn (empty when hidden).
  vtkPolyData* isoLines() const;

 private:
  void attach();
  void update();

  vtkRenderer* renderer_;
  vtkPolyDataMapper* partMapper_;
  vtkSmartPointer<vtkPolyData> surface_;
  std::vector<double> values_;
  QString name_, unit_;
  bool visible_ = false;
  bool attached_ = false;
  std::pair<double, double> dataRange_{0.0, 1.0}, range_{0.0, 1.0};
  int isoCount_ = 12;
  double isoSpacing_ = 0.0;
  vtkNew<vtkContourFilter> contour_;
  vtkNew<vtkPolyDataMapper> isoMapper_;
  vtkNew<vtkActor> isoActor_;
  ColorLegend legend_;
};

}  // namespace spira::ui
