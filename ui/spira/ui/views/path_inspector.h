#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include <QObject>
#include <QPoint>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "spira/base/transform.h"

class QLabel;
class QListWidget;
class QListWidgetItem;
class QStatusBar;
class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkCellPicker;
class vtkPlot;
class vtkSphereSource;
class vtkTable;

namespace spira {
struct Results;
struct Trajectory;
}  // namespace spira

namespace spira::ui {

class FrameGlyphs;
class LogPanel;
class PointSelection;
class ProcessChart;
class SceneView;

// Inspecting the plan point by point: the shared point selection, the marker that shows it in the
// 3D view, the cursor that shows it on the process chart, its channels in the status bar, and the
// ways to pick it: a click on the chart (nearest abscissa), a click on the spiral in the 3D view
// (nearest path point, a drag still rotates), or a click on a message naming an offending point.
// Also draws the torch frames as glyphs on demand. It reads the document's results through
// setResults() and keeps no model state.
class PathInspector : public QObject {
  Q_OBJECT

 public:
  // Role of a messages-panel entry's data holding the path point it names.
  static constexpr int kPointRole = Qt::UserRole + 17;
  static constexpr int kMaxListedPoints = 10;

  // `selection` is the window's, shared with the other views that follow it.
  PathInspector(PointSelection* selection, SceneView* view, ProcessChart* chart, LogPanel* log,
                QStatusBar* status, QObject* parent = nullptr);
  ~PathInspector() override;

  // The results changed (and the chart was given them): the path to inspect is the process
  // stage's, else the spiral's. A selection past the new path's end is cleared.
  void setResults(const Results& results, const Transform& T_world_part);

  PointSelection* selection() const { return selection_; }
  FrameGlyphs& frameGlyphs() const { return *glyphs_; }
  void setFramesVisible(bool on);

  const Trajectory* path() const { return path_.get(); }
  // Arc length from the path's start to each point, mm.
  const std::vector<double>& abscissa() const { return abscissa_; }
  // The path point nearest the abscissa `s` (mm); -1 without a path.
  long long nearestToAbscissa(double s) const;
  // The path point nearest `world` (mm, world frame); -1 without a path.
  long long nearestTo(const Vec3& world) const;
  // Position of point `i` in the world frame.
  Vec3 worldPoint(long long i) const;

  // The chart's point under `pos` (chart widget coordinates): -1 outside the plots.
  long long indexAtChartPosition(const QPoint& pos) const;
  // Where point `i` lies on the chart (chart widget coordinates, on the height curve).
  QPoint chartPositionOf(long long i) const;
  // Picks the spiral under `pos` (3D view widget coordinates): the nearest path point, or -1.
  long long pickInView(const QPoint& pos) const;
  // Where point `i` appears in the 3D view (view widget coordinates).
  QPoint viewPositionOf(long long i) const;

  // The 3D marker: shown with a selection; its centre in the world frame.
  bool markerVisible() const;
  Vec3 markerPosition() const;
  double markerRadius() const;
  // The chart cursor's abscissa in the chart's unit (nullopt when hidden).
  std::optional<double> chartCursor() const;
  QLabel* statusLabel() const { return status_; }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void onSelectionChanged(long long index);
  void updateChartCursor();
  void listOffenders(const Results& results);

  SceneView* view_;
  ProcessChart* chart_;
  LogPanel* log_;
  QVTKOpenGLNativeWidget* chartWidget_ = nullptr;
  QVTKOpenGLNativeWidget* viewWidget_ = nullptr;
  QListWidget* logList_ = nullptr;
  PointSelection* selection_;
  QLabel* status_ = nullptr;
  std::unique_ptr<FrameGlyphs> glyphs_;
  vtkNew<vtkSphereSource> sphere_;
  vtkNew<vtkActor> marker_;
  vtkNew<vtkCellPicker> picker_;
  std::array<vtkPlot*, 2> cursorPlots_{};
  std::array<vtkNew<vtkTable>, 2> cursorTables_;
  std::shared_ptr<const Trajectory> path_;
  bool hasSpeeds_ = false;
  Transform T_world_part_ = Transform::Identity();
  std::vector<double> abscissa_;
  double length_ = 0.0;
  double pathDiagonal_ = 0.0;
  QPoint chartPress_{-1, -1};
  QPoint viewPress_{-1, -1};
};

}  // namespace spira::ui
