#include "spira/ui/views/frame_glyphs.h"

#include <algorithm>
#include <cmath>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include "spira/path/tool_frame.h"
#include "spira/path/trajectory.h"

namespace spira::ui {

FrameGlyphs::FrameGlyphs(vtkRenderer* renderer) : renderer_(renderer)
{
  mapper_->SetInputData(lines_);
  mapper_->SetScalarModeToUseCellData();
  mapper_->SetColorModeToDirectScalars();
  actor_->SetMapper(mapper_);
  actor_->GetProperty()->SetLineWidth(2.0f);
  actor_->GetProperty()->SetLighting(false);
  actor_->SetVisibility(false);
  actor_->SetPickable(false);
  renderer_->AddActor(actor_);
}

FrameGlyphs::~FrameGlyphs()
{
  renderer_->RemoveActor(actor_);
}

void FrameGlyphs::setTrajectory(std::shared_ptr<const Trajectory> path, const Transform& T_world_part)
{
  path_ = std::move(path);
  T_world_part_ = T_world_part;
  dirty_ = true;
  if (visible_ || !path_) rebuild();
  actor_->SetVisibility(visible_ && glyphs_ > 0);
}

void FrameGlyphs::setVisible(bool on)
{
  visible_ = on;
  if (on && dirty_) rebuild();
  actor_->SetVisibility(visible_ && glyphs_ > 0);
}

void FrameGlyphs::rebuild()
{
  dirty_ = false;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  colours->SetName("axis_colour");
  const long long n = path_ ? static_cast<long long>(path_->size()) : 0;
  stride_ = std::max<long long>(1, (n + kMaxGlyphs - 1) / kMaxGlyphs);
  glyphs_ = 0;
  if (n > 0) {
    // Triads sized to the spacing between glyphs along the path (so neighbours do not overlap),
    // bounded by the part's size so that sparse paths do not sprout giant axes.
    Eigen::AlignedBox3d box;
    for (const TrajectoryPoint& p : path_->points) box.extend(p.position);
    const double diagonal = box.diagonal().norm();
    const double spacing = path_->length() / static_cast<double>(std::max<long long>(1, n / stride_));
    length_ = std::clamp(0.8 * spacing, 0.004 * diagonal, 0.03 * diagonal);
    const unsigned char rgb[3][3] = {{220, 50, 47}, {40, 160, 60}, {38, 110, 220}};
    for (long long i = 0; i < n; i += stride_) {
      const Transform T = T_world_part_ * toolFrame(path_->points[static_cast<size_t>(i)]);
      const Vec3 o = T.translation();
      const vtkIdType base = points->InsertNextPoint(o.data());
      for (int a = 0; a < 3; ++a) {
        const Vec3 tip = o + length_ * T.linear().col(a);
        const vtkIdType t = points->InsertNextPoint(tip.data());
        const vtkIdType ids[2] = {base, t};
        cells->InsertNextCell(2, ids);
        colours->InsertNextTypedTuple(rgb[a]);
      }
      ++glyphs_;
    }
  }
  lines_->SetPoints(points);
  lines_->SetLines(cells);
  lines_->GetCellData()->SetScalars(colours);
  lines_->Modified();
}

}  // namespace spira::ui
