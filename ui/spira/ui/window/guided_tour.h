#pragma once

#include <QDialog>
#include <QPointer>

#include "spira/ui/window/window_parts.h"

class QLabel;
class QListWidget;
class QPushButton;

namespace spira::ui {

struct TaskOutcome;

// Help > Guided Sample: a short non-modal list of steps ("open the sample dome, plan, inspect,
// export"). "Do It" performs the current step in the main window and points at the widget that
// matters; a step is ticked when the window reports it done (the dome opened, the plan finished),
// and the list moves on. The window passes its outcomes on through onFileOpened and onPlanFinished.
class GuidedTour : public QDialog {
  Q_OBJECT

 public:
  enum Step { OpenSample = 0, Plan, Inspect, Export, StepCount };

  explicit GuidedTour(const WindowParts& parts);

  int currentStep() const { return current_; }
  bool isDone(int step) const;
  // Performs `step` (the current one by default); returns false when it could not start (the
  // window is busy, no export command is available, ...); the reason is shown in the dialog.
  bool runStep(int step = -1);
  // The dome written for the first step (QStandardPaths::AppDataLocation/samples/dome.stl),
  // made in code like `spira-cli sample dome`.
  static QString sampleDomeFile();
  QLabel* detailLabel() const { return detail_; }

  void onFileOpened(const QString& path, bool ok);
  void onPlanFinished(const TaskOutcome& outcome);

 private:
  void setCurrent(int step);
  void markDone(int step);
  void highlight(QWidget* widget);

  WindowParts parts_;
  QListWidget* list_ = nullptr;
  QLabel* detail_ = nullptr;
  QPushButton* doIt_ = nullptr;
  QPushButton* next_ = nullptr;
  QString samplePath_;
  bool done_[StepCount] = {};
  int current_ = 0;
};

}  // namespace spira::ui
