#pragma once

#include <array>
#include <optional>

#include <QImage>
#include <QWidget>

#include <vtkNew.h>

#include "spira/pipeline/document_plan.h"

class QLabel;
class QVTKOpenGLNativeWidget;
class vtkChartMatrix;
class vtkChartXY;
class vtkContextView;
class vtkGenericOpenGLRenderWindow;
class vtkPlot;
class vtkTable;

namespace spira {
struct Trajectory;
}

namespace spira::ui {

// The process channels of a plan against the curvilinear abscissa along the path, in two stacked
// charts sharing that axis: deposit height with the window's h_min and h_max as dashed lines and
// the points outside it in magenta; travel speed (left axis) with wire-feed speed (right axis).
// A vertical line marks where the build shown in the 3D view ends.
class ProcessChart : public QWidget {
  Q_OBJECT

 public:
  enum Row { HeightRow = 0, TravelSpeedRow = 1, WireFeedRow = 2 };
  static constexpr int kRows = 3;
  static constexpr int kPanels = 2;

  explicit ProcessChart(QWidget* parent = nullptr);
  ~ProcessChart() override;

  // Null clears. Without speeds (the process stage is out of date) their charts stay empty.
  void setPath(const Trajectory* path, bool hasSpeeds, std::optional<PlanWindow> window);
  // Marks the abscissa `s` (mm) where the shown build ends; negative hides the mark.
  void setCursor(double s);

  // The chart a channel is drawn in (travel speed and wire feed share one).
  vtkChartXY* chart(Row row) const;
  // The samples plotted in `row` (columns: abscissa, value).
  vtkTable* table(Row row) const;
  // The dashed window lines of the height chart (two rows each: h_min, then h_max).
  vtkTable* windowTable(int which) const;
  // Abscissa unit on the shared axis: "mm" or "m" for long paths.
  QString abscissaUnit() const { return metres_ ? QStringLiteral("m") : QStringLiteral("mm"); }
  void render();
  QImage grabImage();
  // The OpenGL widget that shows the charts (mouse events of the charts arrive there).
  QVTKOpenGLNativeWidget* vtkWidget() const { return widget_; }

 private:
  QVTKOpenGLNativeWidget* widget_ = nullptr;
  QLabel* empty_ = nullptr;
  QLabel* key_ = nullptr;
  QWidget* page_ = nullptr;
  vtkNew<vtkGenericOpenGLRenderWindow> window_;
  vtkNew<vtkContextView> view_;
  vtkNew<vtkChartMatrix> matrix_;
  std::array<vtkChartXY*, kPanels> panels_{};
  std::array<vtkPlot*, kPanels> cursorPlots_{};
  std::array<vtkNew<vtkTable>, kRows> tables_;
  std::array<vtkNew<vtkTable>, 2> windowLines_;
  vtkNew<vtkTable> violations_;
  std::array<vtkNew<vtkTable>, kPanels> cursors_;
  double length_ = 0.0;
  bool metres_ = false;
};

}  // namespace spira::ui
