#pragma once

#include <array>
#include <memory>

#include <QImage>
#include <QWidget>

#include <vtkNew.h>

class QLabel;
class QVTKOpenGLNativeWidget;
class vtkChartXY;
class vtkContextView;
class vtkGenericOpenGLRenderWindow;
class vtkPlot;
class vtkTable;

namespace spira {
struct ThermalStageResult;
}

namespace spira::ui {

// The temperature against time at one point of the path (its shell node, from the thermal stage's
// frames), with the melting temperature and the interpass limit as dashed horizontal lines and the
// time shown on the part as a vertical mark.
class ProbeChart : public QWidget {
  Q_OBJECT

 public:
  explicit ProbeChart(QWidget* parent = nullptr);
  ~ProbeChart() override;

  // Null clears. `interpassLimitC` 0: no limit line.
  void setResult(std::shared_ptr<const ThermalStageResult> result, double meltingC, double interpassLimitC);
  // The path point whose history is drawn (negative: none) and when the torch reaches it (s;
  // negative: unknown), where its peak is marked: frames a few seconds apart miss the pass itself.
  void setPoint(long long index, double arrival = -1.0);
  long long point() const { return point_; }
  // Marks time t (s); negative hides the mark.
  void setCursorTime(double t);

  // Columns: time (in the axis's unit), temperature (C).
  vtkTable* historyTable() const { return history_; }
  vtkTable* meltingTable() const { return melting_; }
  vtkTable* limitTable() const { return limit_; }
  vtkTable* peakTable() const { return peakMark_; }
  vtkChartXY* chart() const { return chart_; }
  // "s" or "min" (long builds).
  QString timeUnit() const { return minutes_ ? QStringLiteral("min") : QStringLiteral("s"); }
  QString title() const;
  void render();
  QImage grabImage();

 private:
  void update();

  QLabel* empty_ = nullptr;
  QLabel* key_ = nullptr;
  QWidget* page_ = nullptr;
  QVTKOpenGLNativeWidget* widget_ = nullptr;
  vtkNew<vtkGenericOpenGLRenderWindow> window_;
  vtkNew<vtkContextView> view_;
  vtkChartXY* chart_ = nullptr;
  vtkNew<vtkTable> history_, melting_, limit_, cursor_, peakMark_;
  std::array<vtkPlot*, 5> plots_{};
  std::shared_ptr<const ThermalStageResult> result_;
  double meltingC_ = 0.0, limitC_ = 0.0, cursorT_ = -1.0, arrival_ = -1.0;
  long long point_ = -1;
  bool minutes_ = false;
};

}  // namespace spira::ui
