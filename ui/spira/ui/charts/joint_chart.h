#pragma once

#include <memory>
#include <utility>
#include <vector>

#include <QImage>
#include <QPoint>
#include <QWidget>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

class QLabel;
class QVTKOpenGLNativeWidget;
class vtkChartMatrix;
class vtkChartXY;
class vtkContextView;
class vtkGenericOpenGLRenderWindow;
class vtkPlot;
class vtkTable;

namespace spira {
struct AxisLimit;
struct KinematicsResult;
}  // namespace spira

namespace spira::ui {

class PointSelection;

// The robot's axes (A1..A6 or J1..J6, then the positioner's E1, E2) against the point index, one
// small chart per axis in controller degrees, with the axis's limits as red dashed lines, the
// points the robot cannot reach or where the torch collides as magenta dots, and the selected
// point as a vertical cursor. A click on a chart selects the point under it.
class JointChart : public QWidget {
  Q_OBJECT

 public:
  JointChart(PointSelection* selection, QWidget* parent = nullptr);
  ~JointChart() override;

  // Null clears (the kinematics stage is out of date or there is no cell).
  void setKinematics(std::shared_ptr<const KinematicsResult> kinematics);
  bool hasKinematics() const { return kinematics_ != nullptr; }

  int axisCount() const { return static_cast<int>(charts_.size()); }
  vtkChartXY* chart(int axis) const;
  // Columns: point index, degrees.
  vtkTable* table(int axis) const;
  // Rows: the lower limit then the upper one, each as a two-point line (index, degrees).
  vtkTable* limitTable(int axis, int which) const;
  // The point under `pos` (widget coordinates of the VTK view), -1 outside the charts.
  long long indexAt(const QPoint& pos) const;
  // Where point `i` lies on axis `axis`'s curve (VTK view widget coordinates).
  QPoint positionOf(int axis, long long i) const;
  QVTKOpenGLNativeWidget* vtkWidget() const { return widget_; }
  // The cursor's point index (-1 when hidden).
  long long cursor() const { return cursor_; }
  void render();
  QImage grabImage();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  // rebuild(): the charts (made again when the number of axes changes), then per axis its curve
  // with the flagged points, its limit lines and its framing.
  void rebuild();
  void buildCharts(size_t axes);
  void addAxisChart(size_t a, size_t axes, size_t columns);
  std::pair<double, double> fillAxis(const KinematicsResult& k, size_t a);
  void frameAxis(size_t a, const AxisLimit& lim, double last, double lo, double hi);
  void updateCursor();

  PointSelection* selection_;
  std::shared_ptr<const KinematicsResult> kinematics_;
  QVTKOpenGLNativeWidget* widget_ = nullptr;
  QLabel* empty_ = nullptr;
  QWidget* page_ = nullptr;
  QLabel* key_ = nullptr;
  vtkNew<vtkGenericOpenGLRenderWindow> window_;
  vtkNew<vtkContextView> view_;
  vtkSmartPointer<vtkChartMatrix> matrix_;
  std::vector<vtkChartXY*> charts_;
  std::vector<vtkSmartPointer<vtkTable>> tables_, lower_, upper_, flagged_, cursors_;
  std::vector<vtkPlot*> cursorPlots_;
  long long cursor_ = -1;
  QPoint press_{-1, -1};
};

}  // namespace spira::ui
