#include "spira/ui/views/field_layer.h"

#include <algorithm>
#include <cmath>

#include <QObject>

#include <vtkActor.h>
#include <vtkContourFilter.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>

#include "spira/ui/views/color_maps.h"
#include "spira/ui/views/substrate_grid.h"
#include "spira/ui/views/vtk_mesh.h"

namespace spira::ui {

namespace {

constexpr const char* kFieldArray = "field";

}  // namespace

FieldLayer::FieldLayer(vtkRenderer* renderer, vtkPolyDataMapper* partMapper)
    : renderer_(renderer), partMapper_(partMapper), legend_(renderer, ColorLegend::Side::Left)
{
  contour_->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, kFieldArray);
  contour_->ComputeScalarsOff();
  contour_->ComputeNormalsOff();
  isoMapper_->SetInputConnection(contour_->GetOutputPort());
  isoMapper_->ScalarVisibilityOff();
  isoMapper_->SetRelativeCoincidentTopologyLineOffsetParameters(-1.0, -30.0);
  isoActor_->SetMapper(isoMapper_);
  vtkProperty* p = isoActor_->GetProperty();
  p->SetColor(0.10, 0.11, 0.14);
  p->SetLineWidth(1.6);
  p->LightingOff();
  p->SetOpacity(0.85);
  isoActor_->VisibilityOff();
  renderer_->AddActor(isoActor_);
}

FieldLayer::~FieldLayer() = default;

vtkPolyData* FieldLayer::isoLines() const
{
  return contour_->GetOutput();
}

void FieldLayer::setSurface(vtkPolyData* surface)
{
  surface_ = surface;
  attached_ = false;
  attach();
  update();
}

void FieldLayer::setField(const std::vector<double>& values, const QString& name, const QString& unit)
{
  values_ = values;
  name_ = name;
  unit_ = unit;
  if (!values_.empty()) {
    const auto [lo, hi] = std::minmax_element(values_.begin(), values_.end());
    dataRange_ = {*lo, *hi};
    range_ = dataRange_;
  }
  attached_ = false;
  attach();
  update();
}

void FieldLayer::attach()
{
  if (attached_ || !surface_) return;
  surface_->GetPointData()->RemoveArray(kFieldArray);
  auto* ids = vtkIdTypeArray::SafeDownCast(surface_->GetPointData()->GetArray(kVertexIdArray));
  if (values_.empty() || !ids) return;
  const vtkIdType n = surface_->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> field;
  field->SetName(kFieldArray);
  field->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i) {
    const vtkIdType v = ids->GetValue(i);
    // A field of another mesh (the part changed since the plan) is not drawn.
    if (v < 0 || static_cast<size_t>(v) >= values_.size()) return;
    field->SetValue(i, values_[static_cast<size_t>(v)]);
  }
  surface_->GetPointData()->AddArray(field);
  contour_->SetInputData(surface_);
  attached_ = true;
}

void FieldLayer::setVisible(bool on)
{
  visible_ = on;
  update();
}

void FieldLayer::setRange(double lo, double hi)
{
  if (!(hi > lo)) return;
  range_ = {lo, hi};
  update();
}

void FieldLayer::setIsoLineCount(int count)
{
  isoCount_ = std::max(0, count);
  update();
}

void FieldLayer::update()
{
  const bool on = visible_ && attached_;
  if (!on) {
    partMapper_->ScalarVisibilityOff();
    isoActor_->VisibilityOff();
    legend_.setVisible(false);
    isoSpacing_ = 0.0;
    return;
  }
  const auto [lo, hi] = range_;
  vtkSmartPointer<vtkLookupTable> lut = makeLookupTable(ColorMap::Viridis, lo, hi);
  partMapper_->SetLookupTable(lut);
  partMapper_->SetScalarModeToUsePointFieldData();
  partMapper_->SelectColorArray(kFieldArray);
  partMapper_->SetScalarRange(lo, hi);
  partMapper_->UseLookupTableScalarRangeOff();
  partMapper_->InterpolateScalarsBeforeMappingOn();
  partMapper_->ScalarVisibilityOn();

  isoSpacing_ = isoCount_ > 0 ? niceGridSpacing(hi - lo, isoCount_) : 0.0;
  contour_->SetNumberOfContours(0);
  if (isoSpacing_ > 0.0) {
    int i = 0;
    for (double v = std::ceil(lo / isoSpacing_) * isoSpacing_; v <= hi + 1e-9 * isoSpacing_ && i < 1000;
         v += isoSpacing_) {
      // The lowest level is the base edge itself: drawing it adds nothing.
      if (v > dataRange_.first + 1e-9 * isoSpacing_) contour_->SetValue(i++, v);
    }
  }
  isoActor_->SetVisibility(contour_->GetNumberOfContours() > 0);
  contour_->Update();

  legend_.setLookupTable(lut);
  legend_.setLabelFormat(labelFormatFor(lo, hi));
  QString title = unit_.isEmpty() ? name_ : QStringLiteral("%1 (%2)").arg(name_, unit_);
  if (isoSpacing_ > 0.0) {
    title += QObject::tr("\nlines every %1").arg(isoSpacing_, 0, 'g', 4);
    if (!unit_.isEmpty()) title += QLatin1Char(' ') + unit_;
  }
  legend_.setTitle(title);
  legend_.setVisible(true);
}

}  // namespace spira::ui
