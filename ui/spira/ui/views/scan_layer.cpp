#include "spira/ui/views/scan_layer.h"

#include <algorithm>
#include <cmath>

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
#include <QLocale>
#include <QObject>

#include "spira/scan/point_cloud.h"
#include "spira/scan/scan_deviation.h"

namespace spira::ui {

ScanLayer::ScanLayer(vtkRenderer* renderer) : legend_(renderer, ColorLegend::Side::Left)
{
  mapper_->SetInputData(cloud_);
  mapper_->SetScalarModeToUsePointFieldData();
  mapper_->SelectColorArray("deviation");
  mapper_->UseLookupTableScalarRangeOff();
  actor_->SetMapper(mapper_);
  actor_->GetProperty()->SetPointSize(3.0);
  actor_->GetProperty()->LightingOff();
  actor_->GetProperty()->SetColor(0.55, 0.55, 0.58);
  actor_->VisibilityOff();
  renderer->AddActor(actor_);
  legend_.setVisible(false);
}

ScanLayer::~ScanLayer() = default;

void ScanLayer::setScan(const PointCloud& cloud, const std::vector<double>& deviation,
                        const DeviationStats& stats, const Transform& T_world_part)
{
  cloud_->Initialize();
  aligned_ = !deviation.empty();
  count_ = aligned_ ? std::min(cloud.size(), deviation.size()) : cloud.size();
  if (count_ > 0) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(count_));
    vtkNew<vtkFloatArray> values;
    values->SetName("deviation");
    values->SetNumberOfValues(static_cast<vtkIdType>(count_));
    vtkNew<vtkCellArray> vertices;
    for (size_t i = 0; i < count_; ++i) {
      const Vec3 w = T_world_part * cloud.points[i];
      points->SetPoint(static_cast<vtkIdType>(i), w.x(), w.y(), w.z());
      values->SetValue(static_cast<vtkIdType>(i), aligned_ ? static_cast<float>(deviation[i]) : 0.0f);
      vertices->InsertNextCell(1);
      vertices->InsertCellPoint(static_cast<vtkIdType>(i));
    }
    cloud_->SetPoints(points);
    cloud_->SetVerts(vertices);
    cloud_->GetPointData()->AddArray(values);
    // Symmetric about zero so that green is "on the part"; the 95th percentile sets the reach, so a
    // few stray points do not wash the map out.
    limit_ = std::max(stats.p95, 1e-3);
    vtkSmartPointer<vtkLookupTable> lut = makeLookupTable(ColorMap::Window, -limit_, limit_);
    mapper_->SetLookupTable(lut);
    mapper_->SetScalarRange(-limit_, limit_);
    mapper_->SetScalarVisibility(aligned_);
    legend_.setLookupTable(lut);
    legend_.setLabelFormat(labelFormatFor(-limit_, limit_));
    const QLocale locale;
    legend_.setTitle(QObject::tr("Scan deviation (mm), + outside\nmean %1, RMS %2, 95 % within %3")
                         .arg(locale.toString(stats.mean, 'f', 3), locale.toString(stats.rms, 'f', 3),
                              locale.toString(stats.p95, 'f', 3)));
  }
  update();
}

void ScanLayer::setVisible(bool on)
{
  visible_ = on;
  update();
}

void ScanLayer::update()
{
  const bool on = visible_ && count_ > 0;
  actor_->SetVisibility(on);
  legend_.setVisible(on && aligned_);
}

}  // namespace spira::ui
