#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <QMetaType>
#include <QObject>
#include <QString>

class QProgressDialog;
class QThread;
class QTimer;

namespace spira {
class Progress;
}

namespace spira::ui {

struct TaskOutcome {
  enum class Status { Succeeded, Failed, Cancelled };
  Status status = Status::Succeeded;
  QString message;  // Failed: what went wrong
  QString hint;     // Failed: what the user can do

  bool succeeded() const { return status == Status::Succeeded; }
};

// Runs one job at a time on a worker thread. The job reports through the spira::Progress it is
// given and must call checkCancel() in its loops; it must not touch widgets or the Document (hand
// results back through captured state, read them in the `done` handler on the GUI thread).
//
// Progress is shown either in a window-modal dialog with Cancel (imports: the window has nothing
// to offer meanwhile) or only through progressed() (planning: the window stays usable and shows
// progress itself).
//
// Cancel answers within kCancelGraceMs whatever the job does: a job that has not stopped by then
// (a long sparse factorisation checks for cancellation only between steps) is abandoned. It runs
// on to its next checkCancel() with nobody waiting for it, its outcome is dropped, and the next
// job may start at once; the destructor still waits for it.
class TaskRunner : public QObject {
  Q_OBJECT

 public:
  using Job = std::function<void(Progress&)>;
  using Done = std::function<void(const TaskOutcome&)>;
  enum class Display { Dialog, Signals };
  static constexpr int kCancelGraceMs = 50;

  // `dialogParent` is the window the progress dialog is modal to.
  explicit TaskRunner(QWidget* dialogParent, QObject* parent = nullptr);
  ~TaskRunner() override;

  bool busy() const;
  // Starts `job`; `done` runs on the GUI thread when it has finished, before finished() is
  // emitted. Returns false (and does nothing) while another job runs.
  bool start(const QString& title, Job job, Done done = {}, Display display = Display::Dialog);
  void cancel();
  // Runs the event loop until the current job has finished (returns at once when idle).
  void waitForFinished();
  // Jobs cancelled but not yet returned (they finish in the background).
  int abandonedCount() const { return static_cast<int>(abandoned_.size()); }

 signals:
  // Emitted when a job has been handed to its thread.
  void started();
  // Emitted on the GUI thread once the job has returned or thrown, or was abandoned on cancel.
  void finished(const spira::ui::TaskOutcome& outcome);
  // The job's latest report (fraction of the whole job in [0, 1], stage name), polled a few
  // times a second while it runs.
  void progressed(double fraction, const QString& stage);

 private:
  struct Shared;
  void pollProgress();
  void onThreadFinished();
  void abandon();
  void complete(const TaskOutcome& out);

  QWidget* dialogParent_;
  std::shared_ptr<Shared> shared_;
  QThread* thread_ = nullptr;
  std::vector<QThread*> abandoned_;
  QProgressDialog* dialog_ = nullptr;
  QTimer* poll_;
  QTimer* grace_;
  Done done_;
  QString title_;
  double lastFraction_ = -1.0;  // last progress emitted
  std::string lastStage_;
};

}  // namespace spira::ui

Q_DECLARE_METATYPE(spira::ui::TaskOutcome)
