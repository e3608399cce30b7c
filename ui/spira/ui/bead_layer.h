#pragma once

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "spira/base/transform.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkTubeFilter;

namespace spira {
struct KinematicsResult;
}

namespace spira::ui {

// What the simulation draws over the part: the bead deposited so far (a tube along the path up to
// the current point), red markers where the torch or a robot link collides or the robot cannot
// reach (up to the current point), and a marker at the current point.
class BeadLayer {
 public:
  explicit BeadLayer(vtkRenderer* renderer);
  ~BeadLayer();

  // The solved motion (null clears), drawn where T_scene_part places the part; `beadRadius` mm.
  void setMotion(const KinematicsResult* motion, const Transform& T_scene_part, double beadRadius);
  // Shows the build up to point `index` included.
  void showUpTo(size_t index);
  void setVisible(bool on);
  // Flagged points (collision or unreachable) shown at the current index.
  long long shownFlagCount() const { return shownFlags_; }
  long long shownBeadPoints() const { return shownPoints_; }
  vtkActor* beadActor() const { return bead_; }
  vtkActor* flagActor() const { return flags_; }

 private:
  vtkSmartPointer<vtkRenderer> renderer_;  // kept alive until the layer's actors are removed
  vtkNew<vtkPolyData> path_;
  vtkNew<vtkPolyData> shown_;
  vtkNew<vtkTubeFilter> tube_;
  vtkNew<vtkActor> bead_;
  vtkNew<vtkPolyData> flagPoints_;
  vtkNew<vtkActor> flags_;
  vtkNew<vtkPolyData> current_;
  vtkNew<vtkActor> currentActor_;
  const KinematicsResult* motion_ = nullptr;
  bool visible_ = true;
  long long shownFlags_ = 0;
  long long shownPoints_ = 0;
};

}  // namespace spira::ui
