#pragma once

#include <functional>
#include <memory>

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include "spira/ui/panels/simulation_clock.h"

class QDoubleSpinBox;
class QLabel;
class QSlider;
class QToolButton;

namespace spira {
struct KinematicsResult;
}

namespace spira::ui {

class BeadLayer;
class RobotLayer;

// Plays a solved motion: play/pause, step forward/back, a speed (x real time, the path's own
// travel speeds) and a position slider. At each shown point the robot and positioner take that
// point's joints (RobotLayer::setPose: forward kinematics, actors' matrices only), the bead grows
// up to it and collisions met so far stay marked. Playback runs on a GUI-thread timer at ~30 fps.
class SimulationPanel : public QWidget {
  Q_OBJECT

 public:
  SimulationPanel(RobotLayer& robot, BeadLayer& bead, std::function<void()> render,
                  QWidget* parent = nullptr);

  // Null: nothing to play (the panel says why with `reason`).
  void setMotion(std::shared_ptr<const KinematicsResult> motion, const QString& reason = {});
  bool hasMotion() const { return motion_ != nullptr; }
  size_t index() const { return index_; }
  void setIndex(size_t i);
  void stepForward();
  void stepBackward();
  void play();
  void pause();
  bool playing() const { return timer_.isActive(); }
  double speed() const;
  void setSpeed(double timesRealTime);
  QString statusText() const;
  QSlider* slider() const { return slider_; }

 signals:
  void indexChanged(int index);
  // Playback started (true) or stopped (false).
  void playingChanged(bool playing);

 private:
  void tick();
  void updateControls();

  RobotLayer& robot_;
  BeadLayer& bead_;
  std::function<void()> render_;
  std::shared_ptr<const KinematicsResult> motion_;
  SimulationClock clock_;
  size_t index_ = 0;
  double time_ = 0.0;  // simulated seconds since the path's start
  QTimer timer_;
  QElapsedTimer wall_;
  QToolButton* back_;
  QToolButton* playPause_;
  QToolButton* forward_;
  QDoubleSpinBox* speed_;
  QSlider* slider_;
  QLabel* status_;
};

}  // namespace spira::ui
