#pragma once

#include <vtkInteractorStyleTrackballCamera.h>

namespace spira::ui {

// Trackball camera without VTK's single-key commands ('w' wireframe, 'e' exit, 'f' fly-to...):
// keys belong to the application's menus and shortcuts, which users can discover.
class QuietTrackballStyle : public vtkInteractorStyleTrackballCamera {
 public:
  static QuietTrackballStyle* New();
  vtkTypeMacro(QuietTrackballStyle, vtkInteractorStyleTrackballCamera) void OnChar() override {}
  void OnKeyPress() override {}

 protected:
  QuietTrackballStyle() = default;
  ~QuietTrackballStyle() override = default;
};

}  // namespace spira::ui
