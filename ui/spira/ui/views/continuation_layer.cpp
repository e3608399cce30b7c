#include "spira/ui/views/continuation_layer.h"

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
#include "spira/path/trajectory.h"
#include "spira/ui/views/color_maps.h"

namespace spira::ui {

ContinuationLayer::ContinuationLayer(vtkRenderer* renderer)
{
  lineMapper_->SetInputData(polyline_);
  lineMapper_->SetScalarModeToUsePointFieldData();
  lineMapper_->SelectColorArray("height");
  lineMapper_->UseLookupTableScalarRangeOff();
  line_->SetMapper(lineMapper_);
  line_->GetProperty()->SetLineWidth(4.0);
  line_->GetProperty()->SetRenderLinesAsTubes(true);
  line_->VisibilityOff();
  renderer->AddActor(line_);
  startMapper_->SetInputData(start_);
  startActor_->SetMapper(startMapper_);
  startActor_->GetProperty()->SetPointSize(16.0);
  startActor_->GetProperty()->SetRenderPointsAsSpheres(true);
  startActor_->GetProperty()->SetColor(0.95, 0.55, 0.05);
  startActor_->VisibilityOff();
  renderer->AddActor(startActor_);
}

ContinuationLayer::~ContinuationLayer() = default;

void ContinuationLayer::setContinuation(const Trajectory& continuation, double lo, double hi,
                                        const Transform& T_world_part)
{
  polyline_->Initialize();
  start_->Initialize();
  points_ = continuation.size();
  if (points_ == 0) {
    clear();
    return;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkFloatArray> heights;
  heights->SetName("height");
  vtkNew<vtkCellArray> lines;
  // One line per stretch of arc: the travel moves between sub-paths lay nothing.
  std::vector<vtkIdType> run;
  const auto flush = [&] {
    if (run.size() >= 2) lines->InsertNextCell(vtkIdType(run.size()), run.data());
    run.clear();
  };
  for (const TrajectoryPoint& p : continuation.points) {
    const Vec3 w = T_world_part * p.position;
    const vtkIdType id = points->InsertNextPoint(w.x(), w.y(), w.z());
    heights->InsertNextValue(static_cast<float>(p.height));
    if (!p.arcOn) {
      flush();
      continue;
    }
    run.push_back(id);
  }
  flush();
  polyline_->SetPoints(points);
  polyline_->SetLines(lines);
  polyline_->GetPointData()->AddArray(heights);
  const double top = std::max(hi, lo + 1e-6);
  lineMapper_->SetLookupTable(makeLookupTable(ColorMap::Window, lo, top));
  lineMapper_->SetScalarRange(lo, top);
  lineMapper_->ScalarVisibilityOn();

  vtkNew<vtkPoints> first;
  const Vec3 w = T_world_part * continuation.points.front().position;
  first->InsertNextPoint(w.x(), w.y(), w.z());
  vtkNew<vtkCellArray> vertex;
  vertex->InsertNextCell(1);
  vertex->InsertCellPoint(0);
  start_->SetPoints(first);
  start_->SetVerts(vertex);
  line_->VisibilityOn();
  startActor_->VisibilityOn();
}

void ContinuationLayer::clear()
{
  points_ = 0;
  polyline_->Initialize();
  start_->Initialize();
  line_->VisibilityOff();
  startActor_->VisibilityOff();
}

}  // namespace spira::ui
