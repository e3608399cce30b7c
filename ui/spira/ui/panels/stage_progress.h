#pragma once

#include <array>

#include <QWidget>

#include "spira/pipeline/document_plan.h"

class QLabel;
class QProgressBar;
class QPushButton;

namespace spira::ui {

class StatusLine;

// The progress of a running plan, one bar per stage (field, closure point, generatrices, spiral,
// process) with the job's own words on what it is doing, and a Cancel button. Whoever holds it
// shows it while runningChanged(true). Nothing it shows while a plan runs changes its size, so
// progress never relays the window out (the current stage is coloured, not bold; the text is a
// StatusLine).
class StageProgress : public QWidget {
  Q_OBJECT

 public:
  explicit StageProgress(QWidget* parent = nullptr);

  // Resets every bar and enables Cancel. `thermal`: whether the plan runs its optional thermal
  // stage; without it that stage's bar is hidden.
  void start(bool thermal = false);
  // The job reported `fraction` of the whole plan (see planStageSpans) while doing `what`.
  void setProgress(double fraction, const QString& what);
  // Idle again.
  void stop();

  bool running() const { return running_; }

  int currentStage() const { return current_; }
  // Whether the bar of `stage` is shown (the thermal stage's only when the plan runs it).
  bool stageShown(int stage) const;
  // Percent shown by the bar of `stage` (0..100).
  int stagePercent(int stage) const;
  QPushButton* cancelButton() const { return cancel_; }

 signals:
  void cancelRequested();
  void runningChanged(bool running);

 private:
  std::array<QLabel*, kPlanStageCount> labels_{};
  std::array<QProgressBar*, kPlanStageCount> bars_{};
  void highlightStage(int stage);

  StatusLine* what_ = nullptr;
  QPushButton* cancel_ = nullptr;
  int current_ = 0;
  int highlighted_ = -1;
  bool running_ = false;
};

}  // namespace spira::ui
