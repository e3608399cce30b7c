#pragma once

#include <optional>

#include <vtkNew.h>

#include "spira/base/transform.h"

class vtkActor;
class vtkCaptionActor2D;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;
class vtkSphereSource;

namespace spira {
struct Generatrices;
}

namespace spira::ui {

// The decomposition of a plan in the 3D view: the generatrices as thin polylines from the base
// up, a tube's guide curve (constant distance) as a thick line through the tube, and the closure
// point (closed parts) as a marked sphere with a caption.
class PathLayers {
 public:
  explicit PathLayers(vtkRenderer* renderer);
  ~PathLayers();

  // Null clears. The lines are in the part frame, drawn where T_world_part places them;
  // `markerRadius` sizes the closure point (mm).
  void setGeneratrices(const Generatrices* lines, const Transform& T_world_part, double markerRadius);
  void setGeneratricesVisible(bool on);
  bool generatricesVisible() const { return linesVisible_; }
  void setClosureVisible(bool on);
  bool closureVisible() const { return closureVisible_; }
  void setGuideVisible(bool on);
  bool guideVisible() const { return guideVisible_; }
  bool hasGuide() const { return hasGuide_; }

  // Polylines drawn: every stride-th generatrix, so that at most kMaxLines show (hundreds of
  // lines side by side only make a moire).
  static constexpr int kMaxLines = 72;
  long long lineCount() const;
  int stride() const { return stride_; }
  int generatrixCount() const { return generatrixCount_; }
  std::optional<Vec3> closurePoint() const { return closure_; }
  // The positioner carries the part: its 3D actors move with their user matrix, but the 2D
  // caption is pinned to a world point, moved here (identity: at rest).
  void setPartMotion(const Transform& motion);
  // Where the caption points, in the scene.
  Vec3 captionAnchor() const;
  vtkActor* linesActor() const { return lines_; }
  vtkActor* closureActor() const { return marker_; }
  vtkActor* guideActor() const { return guide_; }

 private:
  void updateVisibility();

  vtkNew<vtkPolyData> polylines_;
  vtkNew<vtkPolyDataMapper> linesMapper_;
  vtkNew<vtkActor> lines_;
  vtkNew<vtkPolyData> guideLine_;
  vtkNew<vtkPolyDataMapper> guideMapper_;
  vtkNew<vtkActor> guide_;
  vtkNew<vtkSphereSource> sphere_;
  vtkNew<vtkPolyDataMapper> markerMapper_;
  vtkNew<vtkActor> marker_;
  vtkNew<vtkCaptionActor2D> caption_;
  std::optional<Vec3> closure_;
  Transform motion_ = Transform::Identity();
  bool linesVisible_ = false;
  bool closureVisible_ = true;
  bool guideVisible_ = true;
  bool hasGuide_ = false;
  bool hasLines_ = false;
  int stride_ = 1;
  int generatrixCount_ = 0;
};

}  // namespace spira::ui
