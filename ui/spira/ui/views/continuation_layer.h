#pragma once

#include <vtkNew.h>

#include "spira/base/transform.h"

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;

namespace spira {
struct Trajectory;
}  // namespace spira

namespace spira::ui {

// The rest of a build re-planned from a scan, drawn thick beside the plan as built so far: coloured by
// its deposit heights on the plan's own scale (the spiral's legend), so the beads laid thicker to make
// the wall up stand out, with the point where the arc restarts.
class ContinuationLayer {
 public:
  explicit ContinuationLayer(vtkRenderer* renderer);
  ~ContinuationLayer();

  // An empty trajectory clears the layer.
  // [lo, hi]: the spiral layer's height scale (the window with its tolerance), mm.
  void setContinuation(const Trajectory& continuation, double lo, double hi, const Transform& T_world_part);
  void clear();
  bool hasContinuation() const { return points_ > 0; }
  size_t pointCount() const { return points_; }
  vtkActor* actor() const { return line_; }

 private:
  vtkNew<vtkPolyData> polyline_;
  vtkNew<vtkPolyDataMapper> lineMapper_;
  vtkNew<vtkActor> line_;
  vtkNew<vtkPolyData> start_;
  vtkNew<vtkPolyDataMapper> startMapper_;
  vtkNew<vtkActor> startActor_;
  size_t points_ = 0;
};

}  // namespace spira::ui
