#pragma once

#include <memory>

#include <QDockWidget>
#include <QTimer>

class QLabel;
class QSlider;
class QToolButton;

namespace spira {
struct Results;
struct ThermalStageResult;
}  // namespace spira

namespace spira::ui {

class ProbeChart;
class SceneView;

// The "Thermal" dock: the thermal stage's verdict (hottest peak and interpass, collapse-risk points,
// energy), the time of the build shown on the part (a slider over the frames, played back here or
// following the Simulation dock) and the probe chart of the selected point.
class ThermalPanel : public QDockWidget {
  Q_OBJECT

 public:
  ThermalPanel(SceneView& view, QWidget* parent = nullptr);

  void setResults(const Results& results);
  bool hasResult() const { return result_ != nullptr; }
  // The point whose temperature the chart draws (the window's selection; negative: none, the chart
  // then draws the point with the hottest interpass temperature).
  void setPoint(long long index);
  // Shows the frame at or before simulated time t (s).
  void setTime(double t);
  // Shows the frame at the time the torch reaches path point `index`.
  void setTimeOfPoint(long long index);
  // Colours the part by temperature (the Display dock's "Temperature" part style).
  void showOnPart();
  void play();
  void pause();
  bool playing() const { return timer_.isActive(); }

  QSlider* frameSlider() const { return slider_; }
  QLabel* summaryLabel() const { return summary_; }
  QLabel* timeLabel() const { return time_; }
  ProbeChart* probeChart() const { return chart_; }
  QToolButton* showButton() const { return show_; }

 signals:
  // The part style changed to Temperature here (the Display dock follows).
  void partStyleChanged();

 private:
  void frameChanged(int frame);

  SceneView& view_;
  std::shared_ptr<const ThermalStageResult> result_;
  std::vector<double> pointTimes_;  // s, when the torch reaches each point
  long long selected_ = -1, hottest_ = -1;
  QLabel* summary_ = nullptr;
  QLabel* time_ = nullptr;
  QSlider* slider_ = nullptr;
  QToolButton* show_ = nullptr;
  QToolButton* playPause_ = nullptr;
  ProbeChart* chart_ = nullptr;
  QTimer timer_;
};

}  // namespace spira::ui
