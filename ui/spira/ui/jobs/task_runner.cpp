#include "spira/ui/jobs/task_runner.h"

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
#include "spira/ui/jobs/background_priority.h"

namespace spira::ui {

namespace {

// A broken invariant of Spira's own (or an exception no layer turned into an Error): a bug.
TaskOutcome bugOutcome(const std::exception& e)
{
  TaskOutcome out;
  out.status = TaskOutcome::Status::Failed;
  out.message = QObject::tr("Internal error: %1").arg(QString::fromStdString(e.what()));
  out.hint = QObject::tr("This is a bug in Spira; please report it with the file you used.");
  return out;
}

}  // namespace

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
    : QObject(parent), dialogParent_(dialogParent), poll_(new QTimer(this)), grace_(new QTimer(this))
{
  qRegisterMetaType<TaskOutcome>();
  // 10 Hz: each report repaints the progress, and with the OpenGL views in the window a repaint
  // composes the whole window (10-30 ms on software OpenGL).
  poll_->setInterval(100);
  connect(poll_, &QTimer::timeout, this, &TaskRunner::pollProgress);
  grace_->setSingleShot(true);
  grace_->setInterval(kCancelGraceMs);
  connect(grace_, &QTimer::timeout, this, &TaskRunner::abandon);
}

TaskRunner::~TaskRunner()
{
  // Leaving a running thread behind would crash at exit; ask the jobs to stop and wait.
  if (thread_) {
    shared_->progress.cancel();
    thread_->wait();
    delete thread_;
  }
  for (QThread* t : abandoned_) {
    t->wait();
    delete t;
  }
}

bool TaskRunner::busy() const
{
  return thread_ != nullptr;
}

bool TaskRunner::start(const QString& title, Job job, Done done, Display display)
{
  if (thread_) return false;
  done_ = std::move(done);
  title_ = title;
  shared_ = std::make_shared<Shared>();
  std::shared_ptr<Shared> shared = shared_;
  QThread* thread = QThread::create([shared, job = std::move(job)] {
    const BackgroundPriority yieldToTheGui;
    TaskOutcome out;
    try {
      job(shared->progress);
    } catch (const Cancelled&) {
      out.status = TaskOutcome::Status::Cancelled;
    } catch (const InternalError& e) {
      out = bugOutcome(e);
    } catch (const Error& e) {
      out.status = TaskOutcome::Status::Failed;
      out.message = QString::fromStdString(e.what());
      out.hint = QString::fromStdString(e.hint());
    } catch (const std::bad_alloc&) {
      out.status = TaskOutcome::Status::Failed;
      out.message = QObject::tr("Out of memory.");
      out.hint = QObject::tr("Close other programs or work on a smaller part.");
    } catch (const std::exception& e) {
      out = bugOutcome(e);
    }
    std::lock_guard<std::mutex> lock(shared->mutex);
    shared->outcome = out;
  });
  thread_ = thread;
  connect(thread, &QThread::finished, this, [this, thread] {
    if (thread == thread_) {
      onThreadFinished();
      return;
    }
    // An abandoned job came back: nobody waits for its outcome any more.
    abandoned_.erase(std::remove(abandoned_.begin(), abandoned_.end(), thread), abandoned_.end());
    thread->deleteLater();
  });

  if (display == Display::Dialog) {
    dialog_ = new QProgressDialog(title, tr("Cancel"), 0, 1000, dialogParent_);
    dialog_->setWindowTitle(title);
    dialog_->setWindowModality(Qt::WindowModal);
    // Quick jobs finish before the dialog would flash up.
    dialog_->setMinimumDuration(400);
    dialog_->setAutoClose(false);
    dialog_->setAutoReset(false);
    dialog_->setValue(0);
    connect(dialog_, &QProgressDialog::canceled, this, &TaskRunner::cancel);
  }
  lastFraction_ = -1.0;
  lastStage_.clear();
  poll_->start();
  thread->start();
  emit started();
  return true;
}

void TaskRunner::cancel()
{
  if (!thread_ || shared_->progress.cancelled()) return;
  shared_->progress.cancel();
  if (dialog_) dialog_->setLabelText(tr("Cancelling..."));
  grace_->start();
}

void TaskRunner::pollProgress()
{
  if (!shared_ || !thread_) return;
  double fraction = 0.0;
  std::string stage;
  {
    std::lock_guard<std::mutex> lock(shared_->mutex);
    fraction = shared_->fraction;
    stage = shared_->stage;
  }
  if (shared_->progress.cancelled()) return;
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (fraction == lastFraction_ && stage == lastStage_) return;  // nothing new to repaint
  lastFraction_ = fraction;
  lastStage_ = stage;
  emit progressed(fraction, QString::fromStdString(stage));
  if (!dialog_) return;
  dialog_->setValue(static_cast<int>(1000.0 * fraction));
  // Keep the job's name (which file) above the stage the job reports.
  if (!stage.empty()) dialog_->setLabelText(title_ + QLatin1Char('\n') + QString::fromStdString(stage));
}

void TaskRunner::abandon()
{
  if (!thread_) return;
  abandoned_.push_back(thread_);
  thread_ = nullptr;
  TaskOutcome out;
  out.status = TaskOutcome::Status::Cancelled;
  complete(out);
}

void TaskRunner::onThreadFinished()
{
  grace_->stop();
  thread_->deleteLater();
  thread_ = nullptr;
  TaskOutcome out;
  {
    std::lock_guard<std::mutex> lock(shared_->mutex);
    out = shared_->outcome;
  }
  // A Cancel pressed after the job finished but before its result reached the UI still wins: the
  // user asked for nothing to change, and nothing has changed yet.
  if (shared_->progress.cancelled() && out.status == TaskOutcome::Status::Succeeded) {
    out = TaskOutcome();
    out.status = TaskOutcome::Status::Cancelled;
  }
  complete(out);
}

void TaskRunner::complete(const TaskOutcome& out)
{
  poll_->stop();
  if (dialog_) {
    dialog_->hide();
    dialog_->deleteLater();
    dialog_ = nullptr;
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
