#include "spira/ui/views/path_layers.h"

#include <algorithm>

#include <vtkActor.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include "spira/path/trajectory.h"

namespace spira::ui {

namespace {

// Adds `line` (part frame) to the cells as one polyline, placed by T_world_part.
void addPolyline(vtkPoints* points, vtkCellArray* cells, const Polyline& line, const Transform& T_world_part)
{
  cells->InsertNextCell(static_cast<vtkIdType>(line.size()));
  for (const Vec3& v : line) {
    const Vec3 w = T_world_part * v;
    cells->InsertCellPoint(points->InsertNextPoint(w.x(), w.y(), w.z()));
  }
}

// Replaces the lines of `data`; whether it holds any.
bool setPolylines(vtkPolyData* data, vtkPoints* points, vtkCellArray* cells)
{
  data->Initialize();
  data->SetPoints(points);
  data->SetLines(cells);
  return cells->GetNumberOfCells() > 0;
}

}  // namespace

PathLayers::PathLayers(vtkRenderer* renderer)
{
  linesMapper_->SetInputData(polylines_);
  linesMapper_->ScalarVisibilityOff();
  // Lines lying on the part's triangles would be half hidden by them: draw them in front.
  linesMapper_->SetRelativeCoincidentTopologyLineOffsetParameters(-1.0, -30.0);
  lines_->SetMapper(linesMapper_);
  vtkProperty* p = lines_->GetProperty();
  p->SetColor(0.12, 0.22, 0.42);
  p->SetLineWidth(1.3);
  p->LightingOff();
  lines_->VisibilityOff();
  renderer->AddActor(lines_);

  guideMapper_->SetInputData(guideLine_);
  guideMapper_->ScalarVisibilityOff();
  guide_->SetMapper(guideMapper_);
  vtkProperty* g = guide_->GetProperty();
  g->SetColor(0.05, 0.05, 0.05);  // apart from the height colour map and its magenta
  g->SetLineWidth(3.0);
  g->LightingOff();
  guide_->VisibilityOff();
  renderer->AddActor(guide_);

  sphere_->SetThetaResolution(24);
  sphere_->SetPhiResolution(16);
  markerMapper_->SetInputConnection(sphere_->GetOutputPort());
  marker_->SetMapper(markerMapper_);
  marker_->GetProperty()->SetColor(0.93, 0.36, 0.05);
  marker_->GetProperty()->SetSpecular(0.4);
  marker_->VisibilityOff();
  renderer->AddActor(marker_);

  caption_->SetCaption("Closure point");
  caption_->BorderOff();
  caption_->LeaderOn();
  caption_->ThreeDimensionalLeaderOff();
  caption_->GetCaptionTextProperty()->SetColor(0.55, 0.20, 0.02);
  caption_->GetCaptionTextProperty()->ShadowOff();
  caption_->GetCaptionTextProperty()->BoldOn();
  caption_->GetCaptionTextProperty()->ItalicOff();
  caption_->GetCaptionTextProperty()->SetFontSize(14);
  caption_->GetTextActor()->SetTextScaleModeToNone();
  caption_->GetProperty()->SetColor(0.55, 0.20, 0.02);
  caption_->SetPosition(25, 30);
  caption_->SetWidth(0.14);
  caption_->SetHeight(0.04);
  caption_->VisibilityOff();
  renderer->AddViewProp(caption_);
}

PathLayers::~PathLayers() = default;

void PathLayers::setGeneratrices(const Generatrices* g, const Transform& T_world_part, double markerRadius)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  generatrixCount_ = g ? static_cast<int>(g->lines.size()) : 0;
  stride_ = std::max(1, (generatrixCount_ + kMaxLines - 1) / kMaxLines);
  if (g) {
    for (size_t i = 0; i < g->lines.size(); i += static_cast<size_t>(stride_)) {
      if (g->lines[i].size() >= 2) addPolyline(points, cells, g->lines[i], T_world_part);
    }
  }
  hasLines_ = setPolylines(polylines_, points, cells);
  vtkNew<vtkPoints> guidePoints;
  guidePoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> guideCells;
  if (g && g->guide.size() >= 2) addPolyline(guidePoints, guideCells, g->guide, T_world_part);
  hasGuide_ = setPolylines(guideLine_, guidePoints, guideCells);
  closure_.reset();
  if (g && g->hasClosurePoint) {
    const Vec3 c = T_world_part * g->closurePoint;
    closure_ = c;
    sphere_->SetCenter(c.x(), c.y(), c.z());
    sphere_->SetRadius(markerRadius);
  }
  setPartMotion(motion_);
  updateVisibility();
}

void PathLayers::setPartMotion(const Transform& motion)
{
  motion_ = motion;
  if (!closure_) return;
  const Vec3 c = motion_ * *closure_;
  caption_->SetAttachmentPoint(c.x(), c.y(), c.z());
}

Vec3 PathLayers::captionAnchor() const
{
  const double* c = caption_->GetAttachmentPoint();
  return Vec3(c[0], c[1], c[2]);
}

void PathLayers::setGeneratricesVisible(bool on)
{
  linesVisible_ = on;
  updateVisibility();
}

void PathLayers::setGuideVisible(bool on)
{
  guideVisible_ = on;
  updateVisibility();
}

void PathLayers::setClosureVisible(bool on)
{
  closureVisible_ = on;
  updateVisibility();
}

long long PathLayers::lineCount() const
{
  return polylines_->GetNumberOfLines();
}

void PathLayers::updateVisibility()
{
  lines_->SetVisibility(linesVisible_ && hasLines_);
  guide_->SetVisibility(guideVisible_ && hasGuide_);
  const bool marker = closureVisible_ && closure_.has_value();
  marker_->SetVisibility(marker);
  caption_->SetVisibility(marker);
}

}  // namespace spira::ui
