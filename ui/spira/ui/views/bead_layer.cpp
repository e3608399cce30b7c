#include "spira/ui/views/bead_layer.h"

#include <algorithm>
#include <vector>

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTubeFilter.h>

#include "spira/document/kinematics_result.h"

namespace spira::ui {

namespace {

void styleBead(vtkActor* a)
{
  // Copper-brown: deposited metal, apart from every colour map of the spiral channels.
  a->GetProperty()->SetColor(0.80, 0.42, 0.16);
  a->GetProperty()->SetSpecular(0.5);
  a->GetProperty()->SetSpecularPower(40.0);
}

}  // namespace

BeadLayer::BeadLayer(vtkRenderer* renderer) : renderer_(renderer)
{
  for (vtkActor* a : {bead_.Get(), finished_.Get()}) {
    vtkNew<vtkPolyDataMapper> mapper;
    a->SetMapper(mapper);
    styleBead(a);
  }

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
  for (vtkActor* a : {bead_.Get(), finished_.Get(), flags_.Get(), currentActor_.Get()}) {
    a->VisibilityOff();
    renderer_->AddActor(a);
  }
}

BeadLayer::~BeadLayer()
{
  for (vtkActor* a : {bead_.Get(), finished_.Get(), flags_.Get(), currentActor_.Get()})
    renderer_->RemoveActor(a);
}

void BeadLayer::setMotion(const KinematicsResult* motion, const Transform& T_scene_part, double beadRadius)
{
  motion_ = motion && motion->path.size() > 0 ? motion : nullptr;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  flagged_.clear();
  if (motion_) {
    points->SetNumberOfPoints(static_cast<vtkIdType>(motion_->path.size()));
    for (size_t i = 0; i < motion_->path.size(); ++i) {
      const Vec3 w = T_scene_part * motion_->path.points[i].position;
      points->SetPoint(static_cast<vtkIdType>(i), w.x(), w.y(), w.z());
      if (i < motion_->checks.size() && (motion_->checks[i].collision || !motion_->checks[i].reachable))
        flagged_.push_back(i);
    }
  }
  path_->Initialize();
  path_->SetPoints(points);
  flagPoints_->Initialize();
  flagPoints_->SetPoints(points);
  current_->Initialize();
  current_->SetPoints(points);
  radius_ = beadRadius;
  tipCells_ = 0;
  chunkTubes_.assign(motion_ ? (motion_->path.size() + kChunk - 1) / kChunk : 0, nullptr);
  finishedChunks_ = static_cast<size_t>(-1);
  showFinishedChunks(0);
  showUpTo(0);
}

vtkSmartPointer<vtkPolyData> BeadLayer::tubeOf(size_t first, size_t last) const
{
  vtkNew<vtkCellArray> lines;
  // One polyline per arc-on run of the same sub-path: the bead does not bridge air moves.
  std::vector<vtkIdType> run;
  auto flush = [&] {
    if (run.size() > 1) lines->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
    run.clear();
  };
  for (size_t i = first; i <= last; ++i) {
    const TrajectoryPoint& p = motion_->path.points[i];
    if (i > first && p.path != motion_->path.points[i - 1].path) flush();
    if (p.arcOn)
      run.push_back(static_cast<vtkIdType>(i));
    else
      flush();
  }
  flush();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  if (lines->GetNumberOfCells() == 0) return out;
  vtkNew<vtkPolyData> polylines;
  polylines->SetPoints(path_->GetPoints());
  polylines->SetLines(lines);
  vtkNew<vtkTubeFilter> tube;
  tube->SetInputData(polylines);
  tube->SetNumberOfSides(10);
  tube->SetRadius(radius_);
  tube->CappingOn();
  tube->Update();
  out->ShallowCopy(tube->GetOutput());
  return out;
}

void BeadLayer::showFinishedChunks(size_t count)
{
  if (count == finishedChunks_) return;
  finishedChunks_ = count;
  auto* mapper = vtkPolyDataMapper::SafeDownCast(finished_->GetMapper());
  if (count == 0) {
    mapper->SetInputData(vtkNew<vtkPolyData>().Get());
    return;
  }
  vtkNew<vtkAppendPolyData> append;
  for (size_t c = 0; c < count; ++c) {
    // A chunk shares its last point with the next one, so the tube has no gap at the seam.
    if (!chunkTubes_[c])
      chunkTubes_[c] = tubeOf(c * kChunk, std::min((c + 1) * kChunk, motion_->path.size() - 1));
    append->AddInputData(chunkTubes_[c]);
  }
  append->Update();
  vtkNew<vtkPolyData> all;
  all->ShallowCopy(append->GetOutput());
  mapper->SetInputData(all);
}

void BeadLayer::showUpTo(size_t index)
{
  shownFlags_ = shownPoints_ = 0;
  if (!motion_) {
    setVisible(visible_);
    return;
  }
  const size_t last = std::min(index, motion_->path.size() - 1);
  const size_t complete = last / kChunk;  // chunks whose points are all laid (their shared last one too)
  showFinishedChunks(complete);
  vtkSmartPointer<vtkPolyData> tip = tubeOf(complete * kChunk, last);
  vtkPolyDataMapper::SafeDownCast(bead_->GetMapper())->SetInputData(tip);
  tipCells_ = tip->GetNumberOfCells();

  vtkNew<vtkCellArray> flags;
  const auto end = std::upper_bound(flagged_.begin(), flagged_.end(), last);
  for (auto it = flagged_.begin(); it != end; ++it) {
    const vtkIdType id = static_cast<vtkIdType>(*it);
    flags->InsertNextCell(1, &id);
  }
  shownFlags_ = static_cast<long long>(end - flagged_.begin());
  shownPoints_ = static_cast<long long>(last + 1);
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
  bead_->SetVisibility(on && motion_ != nullptr && tipCells_ > 0);
  finished_->SetVisibility(on && motion_ != nullptr && finishedChunks_ > 0);
  flags_->SetVisibility(on && shownFlags_ > 0);
  currentActor_->SetVisibility(on && motion_ != nullptr);
}

std::array<double, 6> BeadLayer::beadBounds() const
{
  std::array<double, 6> b{1, -1, 1, -1, 1, -1};
  for (vtkActor* a : {bead_.Get(), finished_.Get()}) {
    if (!a->GetVisibility()) continue;
    a->GetMapper()->Update();
    double ab[6];
    a->GetMapper()->GetBounds(ab);
    for (int i = 0; i < 3; ++i) {
      const bool empty = b[2 * i] > b[2 * i + 1];
      b[2 * i] = empty ? ab[2 * i] : std::min(b[2 * i], ab[2 * i]);
      b[2 * i + 1] = empty ? ab[2 * i + 1] : std::max(b[2 * i + 1], ab[2 * i + 1]);
    }
  }
  return b;
}

}  // namespace spira::ui
