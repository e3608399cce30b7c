#pragma once

#include <utility>
#include <vector>

#include <QObject>

#include <vtkWeakPointer.h>

class QTimer;
class vtkActor;
class vtkInteractorObserver;
class vtkRenderWindow;
class vtkRenderer;

namespace spira::ui {

class SceneView;

// Draws the 3D view fast while the user turns, pans or zooms it (no multisampling, 1-pixel lines)
// and at full quality again once the camera has been still for a moment. On software OpenGL
// (Xvfb, remote desktops) 4x multisampling and wide lines (a geometry-shader pass) make most of
// a frame's cost: a 1,000,000-point spiral draws in about 45 ms instead of 220 ms. Moving pictures
// do not need them; still pictures (and screenshots) keep them.
class InteractiveQuality : public QObject {
  Q_OBJECT

 public:
  // Watches `view`'s interactor style; a child of `view`.
  explicit InteractiveQuality(SceneView* view, int settleMs = 200);
  ~InteractiveQuality() override;

  // What the style's start and end of an interaction do (public for benchmarks and tests).
  void interactionStarted();
  void interactionEnded();
  // One fast frame now (a colouring or build-range change), the full-quality one when idle.
  void fastFrame();
  bool fast() const { return fast_; }
  // While a background job runs or the simulation plays, frames stay fast: the job competes with
  // the renderer for the same cores, and a full-quality software-OpenGL frame of a large part
  // (80-130 ms the first time) would freeze the window; playback is a moving picture. Holds
  // count: full quality returns once every hold is released and the view is still.
  void hold();
  void release();
  bool held() const { return holds_ > 0; }
  // Full quality for the next frame, now (a screenshot is a still picture); no render.
  void fullQualityNow();

 private:
  void restore();
  void applyFullQuality();

  SceneView* view_;
  // The view's VTK objects, weakly: this object (a child of the view) outlives the view's scene.
  vtkWeakPointer<vtkRenderer> renderer_;
  vtkWeakPointer<vtkRenderWindow> window_;
  vtkWeakPointer<vtkInteractorObserver> style_;
  QTimer* settle_ = nullptr;
  unsigned long startTag_ = 0, endTag_ = 0;
  int samples_ = 0;
  std::vector<std::pair<vtkWeakPointer<vtkActor>, double>> widths_;  // wide-line actors and their widths
  bool fast_ = false;
  int holds_ = 0;
};

}  // namespace spira::ui
