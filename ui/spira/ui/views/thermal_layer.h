#pragma once

#include <cstddef>
#include <memory>

#include <vtkNew.h>

#include "spira/base/transform.h"
#include "spira/ui/views/color_maps.h"

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;

namespace spira {
struct ThermalStageResult;
}

namespace spira::ui {

// The deposit coloured by its temperature at one frame of the thermal stage: the shell the model
// solved on, only the elements laid by then, on a fixed scale over the whole build (so colours
// compare from frame to frame), with a legend in degrees Celsius.
class ThermalLayer {
 public:
  explicit ThermalLayer(vtkRenderer* renderer);
  ~ThermalLayer();

  // Null clears. Positions are in the part frame, drawn where T_world_part places them.
  void setResult(std::shared_ptr<const ThermalStageResult> result, double meltingC,
                 const Transform& T_world_part = Transform::Identity());
  bool hasResult() const { return result_ != nullptr; }
  // Shows frame `frame` (clamped to the frames).
  void setFrame(size_t frame);
  size_t frame() const { return frame_; }
  size_t frameCount() const;
  double frameTime() const;  // s
  // Triangles drawn at the current frame (laid by then).
  long long shownTriangles() const { return shownTriangles_; }
  void setVisible(bool on);
  bool visible() const { return visible_; }
  const ColorLegend& legend() const { return legend_; }
  vtkActor* actor() const { return actor_; }

 private:
  void update();

  vtkRenderer* renderer_;
  std::shared_ptr<const ThermalStageResult> result_;
  vtkNew<vtkPolyData> shell_;
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
  ColorLegend legend_;
  double meltingC_ = 0.0;
  size_t frame_ = 0;
  long long shownTriangles_ = 0;
  bool visible_ = false;
};

}  // namespace spira::ui
