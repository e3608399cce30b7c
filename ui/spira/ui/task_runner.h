#pragma once

#include <functional>
#include <memory>

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

// Runs one job at a time on a worker thread while a window-modal progress dialog shows its
// progress and offers Cancel. The job reports through the spira::Progress it is given and must
// call checkCancel() in its loops; it must not touch widgets or the Document (hand results back
// through captured state, read them in the finished() handler on the GUI thread).
class TaskRunner : public QObject {
  Q_OBJECT

 public:
  using Job = std::function<void(Progress&)>;
  using Done = std::function<void(const TaskOutcome&)>;

  // `dialogParent` is the window the progress dialog is modal to.
  explicit TaskRunner(QWidget* dialogParent, QObject* parent = nullptr);
  ~TaskRunner() override;

  bool busy() const;
  // Starts `job`; `done` runs on the GUI thread when it has finished, before finished() is
  // emitted. Returns false (and does nothing) while another job runs.
  bool start(const QString& title, Job job, Done done = {});
  void cancel();
  // Runs the event loop until the current job has finished (returns at once when idle).
  void waitForFinished();

 signals:
  // Emitted on the GUI thread once the job has returned or thrown.
  void finished(const spira::ui::TaskOutcome& outcome);

 private:
  struct Shared;
  void pollProgress();
  void onThreadFinished();

  QWidget* dialogParent_;
  std::shared_ptr<Shared> shared_;
  QThread* thread_ = nullptr;
  QProgressDialog* dialog_ = nullptr;
  QTimer* poll_;
  Done done_;
  QString title_;
};

}  // namespace spira::ui

Q_DECLARE_METATYPE(spira::ui::TaskOutcome)
