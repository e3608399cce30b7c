#include "spira/ui/task_runner.h"

#include <algorithm>
#include <mutex>
#include <new>
#include <string>

#include <QEventLoop>
#include <QProgressDialog>
#include <QThread>
#include <QTimer>

#include "spira/base/error.h"
#include "spira/base/progress.h"

namespace spira::ui {

// State the worker writes and the GUI thread reads. Progress is polled by a timer instead of
// posted per report: a job may report thousands of times a second.
struct TaskRunner::Shared {
  std::mutex mutex;
  double fraction = 0.0;
  std::string stage;
  TaskOutcome outcome;
  CallbackProgress progress{[this](double f, std::string_view s) {
    std::lock_guard<std::mutex> lock(mutex);
    fraction = f;
    stage.assign(s.data(), s.size());
  }};
};

TaskRunner::TaskRunner(QWidget* dialogParent, QObject* parent)
    : QObject(parent), dialogParent_(dialogParent), poll_(new QTimer(this))
{
  qRegisterMetaType<TaskOutcome>();
  poll_->setInterval(50);
  connect(poll_, &QTimer::timeout, this, &TaskRunner::pollProgress);
}

TaskRunner::~TaskRunner()
{
  if (thread_) {
    // Leaving a running thread behind would crash at exit; ask the job to stop and wait.
    shared_->progress.cancel();
    thread_->wait();
  }
}

bool TaskRunner::busy() const
{
  return thread_ != nullptr;
}

bool TaskRunner::start(const QString& title, Job job, Done done)
{
  if (thread_) return false;
  done_ = std::move(done);
  title_ = title;
  shared_ = std::make_shared<Shared>();
  std::shared_ptr<Shared> shared = shared_;
  thread_ = QThread::create([shared, job = std::move(job)] {
    TaskOutcome out;
    try {
      job(shared->progress);
    } catch (const Cancelled&) {
      out.status = TaskOutcome::Status::Cancelled;
    } catch (const Error& e) {
      out.status = TaskOutcome::Status::Failed;
      out.message = QString::fromStdString(e.what());
      out.hint = QString::fromStdString(e.hint());
    } catch (const std::bad_alloc&) {
      out.status = TaskOutcome::Status::Failed;
      out.message = QObject::tr("Out of memory.");
      out.hint = QObject::tr("Close other programs or work on a smaller part.");
    } catch (const std::exception& e) {
      out.status = TaskOutcome::Status::Failed;
      out.message = QObject::tr("Internal error: %1").arg(QString::fromStdString(e.what()));
      out.hint = QObject::tr("This is a bug in Spira; please report it with the file you used.");
    }
    std::lock_guard<std::mutex> lock(shared->mutex);
    shared->outcome = out;
  });
  connect(thread_, &QThread::finished, this, &TaskRunner::onThreadFinished);

  dialog_ = new QProgressDialog(title, tr("Cancel"), 0, 1000, dialogParent_);
  dialog_->setWindowTitle(title);
  dialog_->setWindowModality(Qt::WindowModal);
  // Quick jobs finish before the dialog would flash up.
  dialog_->setMinimumDuration(400);
  dialog_->setAutoClose(false);
  dialog_->setAutoReset(false);
  dialog_->setValue(0);
  connect(dialog_, &QProgressDialog::canceled, this, &TaskRunner::cancel);
  poll_->start();
  thread_->start();
  return true;
}

void TaskRunner::cancel()
{
  if (!shared_) return;
  shared_->progress.cancel();
  if (dialog_) dialog_->setLabelText(tr("Cancelling..."));
}

void TaskRunner::pollProgress()
{
  if (!dialog_ || !shared_) return;
  double fraction = 0.0;
  std::string stage;
  {
    std::lock_guard<std::mutex> lock(shared_->mutex);
    fraction = shared_->fraction;
    stage = shared_->stage;
  }
  if (shared_->progress.cancelled()) return;
  dialog_->setValue(static_cast<int>(1000.0 * std::clamp(fraction, 0.0, 1.0)));
  // Keep the job's name (which file) above the stage the job reports.
  if (!stage.empty()) dialog_->setLabelText(title_ + QLatin1Char('\n') + QString::fromStdString(stage));
}

void TaskRunner::onThreadFinished()
{
  poll_->stop();
  thread_->deleteLater();
  thread_ = nullptr;
  if (dialog_) {
    dialog_->hide();
    dialog_->deleteLater();
    dialog_ = nullptr;
  }
  TaskOutcome out;
  {
    std::lock_guard<std::mutex> lock(shared_->mutex);
    out = shared_->outcome;
  }
  Done done = std::move(done_);
  done_ = nullptr;
  if (done) done(out);
  emit finished(out);
}

void TaskRunner::waitForFinished()
{
  if (!thread_) return;
  QEventLoop loop;
  connect(this, &TaskRunner::finished, &loop, &QEventLoop::quit);
  loop.exec();
}

}  // namespace spira::ui
