#include "spira/ui/views/thermal_layer.h"

#include <algorithm>
#include <cmath>

#include <QLocale>
#include <QObject>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "spira/document/thermal_result.h"

namespace spira::ui {

ThermalLayer::ThermalLayer(vtkRenderer* renderer)
    : renderer_(renderer), legend_(renderer, ColorLegend::Side::Left)
{
  mapper_->SetInputData(shell_);
  mapper_->SetScalarModeToUsePointFieldData();
  mapper_->SelectColorArray("temperature");
  mapper_->InterpolateScalarsBeforeMappingOn();
  mapper_->UseLookupTableScalarRangeOff();
  actor_->SetMapper(mapper_);
  actor_->GetProperty()->SetSpecular(0.05);
  actor_->GetProperty()->SetAmbient(0.2);
  actor_->VisibilityOff();
  renderer_->AddActor(actor_);
  legend_.setVisible(false);
}

ThermalLayer::~ThermalLayer() = default;

void ThermalLayer::setResult(std::shared_ptr<const ThermalStageResult> result, double meltingC,
                             const Transform& T_world_part)
{
  result_ = result && !result->frames.empty() && !result->nodes.empty() ? std::move(result) : nullptr;
  meltingC_ = meltingC;
  frame_ = 0;
  shell_->Initialize();
  if (result_) {
    vtkNew<vtkPoints> points;
    points->SetNumberOfPoints(static_cast<vtkIdType>(result_->nodes.size()));
    for (size_t i = 0; i < result_->nodes.size(); ++i) {
      const Vec3 w = T_world_part * result_->nodes[i];
      points->SetPoint(static_cast<vtkIdType>(i), w.x(), w.y(), w.z());
    }
    shell_->SetPoints(points);
    vtkNew<vtkFloatArray> temperature;
    temperature->SetName("temperature");
    temperature->SetNumberOfValues(points->GetNumberOfPoints());
    shell_->GetPointData()->AddArray(temperature);
    // One scale for every frame, from the coolest value any frame holds to the melting temperature:
    // the node under the point source peaks far above it, and a scale up to there would leave the
    // solid deposit, where the interpass question lies, in one dark colour. Molten: the top colour.
    // Nothing is colder than 0 C in a build: a solver's undershoot below it is not worth the scale.
    const double lo = std::max(result_->frames.offset, 0.0),
                 hottest =
                     result_->frames.offset + result_->frames.step * (ThermalFrameSet::kNotDeposited - 1);
    const double hi = meltingC_ > lo ? std::min(hottest, meltingC_) : hottest;
    vtkSmartPointer<vtkLookupTable> lut = makeLookupTable(ColorMap::Inferno, lo, hi);
    mapper_->SetLookupTable(lut);
    mapper_->SetScalarRange(lo, hi);
    mapper_->ScalarVisibilityOn();
    legend_.setLookupTable(lut);
    legend_.setLabelFormat(QStringLiteral("%.0f"));
    legend_.setTitle(QObject::tr("Temperature (°C)\ntop colour: molten (%1 °C)")
                         .arg(QLocale().toString(meltingC_, 'f', 0)));
    frame_ = result_->frames.size() - 1;
  }
  update();
}

size_t ThermalLayer::frameCount() const
{
  return result_ ? result_->frames.size() : 0;
}

double ThermalLayer::frameTime() const
{
  return result_ ? result_->frames.times[frame_] : 0.0;
}

void ThermalLayer::setFrame(size_t frame)
{
  if (!result_) return;
  frame_ = std::min(frame, result_->frames.size() - 1);
  update();
}

void ThermalLayer::setVisible(bool on)
{
  visible_ = on;
  update();
}

void ThermalLayer::update()
{
  const bool on = visible_ && result_;
  actor_->SetVisibility(on);
  legend_.setVisible(on);
  shownTriangles_ = 0;
  if (!result_) return;
  auto* temperature = vtkFloatArray::SafeDownCast(shell_->GetPointData()->GetArray("temperature"));
  const ThermalFrameSet& frames = result_->frames;
  for (size_t n = 0; n < result_->nodes.size(); ++n) {
    const float t = frames.at(frame_, n);
    temperature->SetValue(static_cast<vtkIdType>(n), std::isfinite(t) ? t : 0.0f);
  }
  temperature->Modified();
  // Only what the torch has laid by then: a triangle whose corners are all deposited.
  vtkNew<vtkCellArray> cells;
  for (const auto& tri : result_->triangles) {
    if (!std::isfinite(frames.at(frame_, static_cast<size_t>(tri[0]))) ||
        !std::isfinite(frames.at(frame_, static_cast<size_t>(tri[1]))) ||
        !std::isfinite(frames.at(frame_, static_cast<size_t>(tri[2]))))
      continue;
    const vtkIdType ids[3] = {tri[0], tri[1], tri[2]};
    cells->InsertNextCell(3, ids);
    ++shownTriangles_;
  }
  shell_->SetPolys(cells);
  shell_->Modified();
}

}  // namespace spira::ui
