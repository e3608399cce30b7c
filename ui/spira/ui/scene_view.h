#pragma once

#include <memory>
#include <optional>

#include <QImage>
#include <QWidget>

class QVTKOpenGLNativeWidget;
class vtkRenderer;

namespace spira {
struct TriangleMesh;
}

namespace spira::ui {

enum class CameraPreset { Iso, Front, Top, Side };

// The central 3D view: the part shaded (edges on demand), the substrate plate with a grid, an
// orientation marker and an optional bounding box. It draws what it is given and keeps no model
// state of its own; the main window feeds it from the document.
class SceneView : public QWidget {
  Q_OBJECT

 public:
  explicit SceneView(QWidget* parent = nullptr);
  ~SceneView() override;

  // Shows `mesh` as the part (nullptr: no part, an empty-scene hint instead). When the part's
  // extent changed the camera goes back to the iso view fitted to the part.
  void showPart(const TriangleMesh* mesh);
  // Shows the substrate plate at height `z` (mm), sized from the part's footprint; nullopt hides it.
  void showSubstrate(std::optional<double> z);

  void setEdgesVisible(bool on);
  bool edgesVisible() const;
  void setBoundingBoxVisible(bool on);
  bool boundingBoxVisible() const;

  void setCameraPreset(CameraPreset preset);
  // Frames the part (or the plate when there is no part) without changing the view direction.
  void fitView();

  // Renders now and returns the 3D view's pixels.
  QImage grabImage();
  // Renders now; changes made through this class otherwise render once control returns to the
  // event loop.
  void render();

  vtkRenderer* renderer() const;
  // Whether the view got an OpenGL context (false on a platform without OpenGL, where it stays
  // blank). Meaningful once the window has been shown.
  bool hasOpenGL() const;
  bool hasPart() const;

 private:
  struct Scene;
  void updateSubstrate();
  void scheduleRender();
  bool renderPending_ = false;
  std::unique_ptr<Scene> scene_;
  QVTKOpenGLNativeWidget* vtkWidget_ = nullptr;
};

}  // namespace spira::ui
