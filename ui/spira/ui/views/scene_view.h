#pragma once

#include <memory>
#include <optional>

#include <vtkSmartPointer.h>
#include <QImage>
#include <QWidget>

#include "spira/base/transform.h"

class QTimer;
class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace spira {
struct BoundingBox;
struct TriangleMesh;
struct Results;
}  // namespace spira

namespace spira::ui {

class FieldLayer;
class PathLayers;
class SpiralLayer;
class ThermalLayer;
class ScanLayer;

enum class CameraPreset { Iso, Front, Top, Side };

// How the part's surface is drawn under the plan's curves.
enum class PartStyle {
  Shaded,       // plain metal
  Field,        // coloured by the plan's scalar field, with iso-lines
  Transparent,  // a faint ghost, so the spiral on it reads clearly
  Hidden,
  Temperature,  // the deposit as laid by a time of the build, coloured by its temperature then
};

// The central 3D view: the part shaded (edges on demand), the substrate plate with a grid, an
// orientation marker and an optional bounding box. It draws what it is given and keeps no model
// state of its own; the main window feeds it from the document.
class SceneView : public QWidget {
  Q_OBJECT

 public:
  explicit SceneView(QWidget* parent = nullptr);
  ~SceneView() override;

  // Shows `mesh` as the part (nullptr: no part, an empty-scene hint instead). When the part's
  // extent changed the camera goes back to the iso view fitted to the part. `shaded` is the mesh's
  // toShadedPolyData() when the caller already built it (an import job does, off this thread:
  // 40-50 ms for 100,000 triangles); null builds it here.
  void showPart(const TriangleMesh* mesh, vtkSmartPointer<vtkPolyData> shaded = nullptr);
  // Shows the substrate plate at height `z` (mm), sized from the part's footprint; nullopt hides it.
  void showSubstrate(std::optional<double> z);
  // Shows a substrate mesh (a pipe, a curved plate the part is built on), in the world frame; nullptr
  // hides it.
  void showSubstrateMesh(const TriangleMesh* mesh);

  // Shows a plan's results (field, generatrices, closure point, spiral) computed in the part
  // frame, drawn where T_world_part places the part.
  void showResults(const Results& results, const Transform& T_world_part);
  // The OpenGL widget that shows the scene (mouse events of the view arrive there).
  QVTKOpenGLNativeWidget* vtkWidget() const { return vtkWidget_; }
  FieldLayer& fieldLayer();
  PathLayers& pathLayers();
  SpiralLayer& spiralLayer();
  ThermalLayer& thermalLayer();
  ScanLayer& scanLayer();
  void setPartStyle(PartStyle style);
  PartStyle partStyle() const;
  // Renders soon (once control returns to the event loop), after a layer was changed.
  void scheduleRender();

  void setEdgesVisible(bool on);
  bool edgesVisible() const;
  void setBoundingBoxVisible(bool on);
  bool boundingBoxVisible() const;

  void setCameraPreset(CameraPreset preset);
  // Frames the part (or the plate when there is no part) without changing the view direction.
  void fitView();
  // Fits the part and `extra` (world frame; a scan not yet placed on the part).
  void fitViewIncluding(const BoundingBox& extra);
  // The part's surface, for picking places on it.
  vtkActor* partActor() const;

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
  void applyPartStyle();
  bool renderPending_ = false;
  QTimer* renderTimer_ = nullptr;
  std::unique_ptr<Scene> scene_;
  QVTKOpenGLNativeWidget* vtkWidget_ = nullptr;
};

}  // namespace spira::ui
