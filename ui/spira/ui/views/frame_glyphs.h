#pragma once

#include <memory>

#include <vtkNew.h>

#include "spira/base/transform.h"

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;

namespace spira {
struct Trajectory;
}

namespace spira::ui {

// Torch frames along the path as small axis triads (x red: travel, y green, z blue: the torch
// axis towards the deposit, see tool_frame.h), one every stride() points so that at most
// kMaxGlyphs are drawn however long the path is. Built only while shown.
class FrameGlyphs {
 public:
  static constexpr long long kMaxGlyphs = 2000;

  explicit FrameGlyphs(vtkRenderer* renderer);
  ~FrameGlyphs();

  // Null clears. Positions are in the part frame, drawn where T_world_part places them.
  void setTrajectory(std::shared_ptr<const Trajectory> path,
                     const Transform& T_world_part = Transform::Identity());
  void setVisible(bool on);
  bool visible() const { return visible_; }

  long long stride() const { return stride_; }
  long long glyphCount() const { return glyphs_; }
  double axisLength() const { return length_; }
  vtkPolyData* polyData() const { return lines_; }
  vtkActor* actor() const { return actor_; }

 private:
  void rebuild();

  vtkRenderer* renderer_;
  vtkNew<vtkPolyData> lines_;
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
  std::shared_ptr<const Trajectory> path_;
  Transform T_world_part_ = Transform::Identity();
  bool visible_ = false;
  bool dirty_ = false;
  long long stride_ = 1;
  long long glyphs_ = 0;
  double length_ = 0.0;
};

}  // namespace spira::ui
