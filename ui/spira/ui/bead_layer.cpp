#include "spira/ui/bead_layer.h"

#include <algorithm>
#include <vector>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTubeFilter.h>

#include "spira/document/kinematics_result.h"

namespace spira::ui {

BeadLayer::BeadLayer(vtkRenderer* renderer) : renderer_(renderer)
{
  tube_->SetInputData(shown_);
  tube_->SetNumberOfSides(10);
  tube_->CappingOn();
  vtkNew<vtkPolyDataMapper> beadMapper;
  beadMapper->SetInputConnection(tube_->GetOutputPort());
  bead_->SetMapper(beadMapper);
  // Copper-brown: deposited metal, apart from every colour map of the spiral channels.
  bead_->GetProperty()->SetColor(0.80, 0.42, 0.16);
  bead_->GetProperty()->SetSpecular(0.5);
  bead_->GetProperty()->SetSpecularPower(40.0);

  vtkNew<vtkPolyDataMapper> flagMapper;
  flagMapper->SetInputData(flagPoints_);
  flags_->SetMapper(flagMapper);
  flags_->GetProperty()->SetColor(0.95, 0.05, 0.05);
  flags_->GetProperty()->SetPointSize(9.0);
  flags_->GetProperty()->SetRenderPointsAsSpheres(true);

  vtkNew<vtkPolyDataMapper> currentMapper;
  currentMapper->SetInputData(current_);
  currentActor_->SetMapper(currentMapper);
  currentActor_->GetProperty()->SetColor(1.0, 0.95, 0.3);
  currentActor_->GetProperty()->SetPointSize(11.0);
  currentActor_->GetProperty()->SetRenderPointsAsSpheres(true);
  for (vtkActor* a : {bead_.Get(), flags_.Get(), currentActor_.Get()}) {
    a->VisibilityOff();
    renderer_->AddActor(a);
  }
}

BeadLayer::~BeadLayer()
{
  for (vtkActor* a : {bead_.Get(), flags_.Get(), currentActor_.Get()}) renderer_->RemoveActor(a);
}

void BeadLayer::setMotion(const KinematicsResult* motion, const Transform& T_scene_part, double beadRadius)
{
  motion_ = motion && motion->path.size() > 0 ? motion : nullptr;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  if (motion_) {
    points->SetNumberOfPoints(static_cast<vtkIdType>(motion_->path.size()));
    for (size_t i = 0; i < motion_->path.size(); ++i) {
      const Vec3 w = T_scene_part * motion_->path.points[i].position;
      points->SetPoint(static_cast<vtkIdType>(i), w.x(), w.y(), w.z());
    }
  }
  path_->Initialize();
  path_->SetPoints(points);
  shown_->Initialize();
  shown_->SetPoints(points);
  flagPoints_->Initialize();
  flagPoints_->SetPoints(points);
  current_->Initialize();
  current_->SetPoints(points);
  tube_->SetRadius(beadRadius);
  showUpTo(0);
}

void BeadLayer::showUpTo(size_t index)
{
  shownFlags_ = shownPoints_ = 0;
  if (!motion_) {
    setVisible(visible_);
    return;
  }
  const size_t last = std::min(index, motion_->path.size() - 1);
  vtkNew<vtkCellArray> lines;
  // One polyline per arc-on run of the same sub-path: the bead does not bridge air moves.
  std::vector<vtkIdType> run;
  auto flush = [&] {
    if (run.size() > 1) lines->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
    run.clear();
  };
  vtkNew<vtkCellArray> flags;
  for (size_t i = 0; i <= last; ++i) {
    const TrajectoryPoint& p = motion_->path.points[i];
    if (i > 0 && p.path != motion_->path.points[i - 1].path) flush();
    if (p.arcOn)
      run.push_back(static_cast<vtkIdType>(i));
    else
      flush();
    if (i < motion_->checks.size() && (motion_->checks[i].collision || !motion_->checks[i].reachable)) {
      const vtkIdType id = static_cast<vtkIdType>(i);
      flags->InsertNextCell(1, &id);
      ++shownFlags_;
    }
  }
  flush();
  shownPoints_ = static_cast<long long>(last + 1);
  shown_->SetLines(lines);
  shown_->Modified();
  flagPoints_->SetVerts(flags);
  flagPoints_->Modified();
  vtkNew<vtkCellArray> cur;
  const vtkIdType id = static_cast<vtkIdType>(last);
  cur->InsertNextCell(1, &id);
  current_->SetVerts(cur);
  current_->Modified();
  setVisible(visible_);
}

void BeadLayer::setVisible(bool on)
{
  visible_ = on;
  bead_->SetVisibility(on && motion_ != nullptr && shownPoints_ > 1);
  flags_->SetVisibility(on && shownFlags_ > 0);
  currentActor_->SetVisibility(on && motion_ != nullptr);
}

}  // namespace spira::ui
