// The worker-thread runner behind imports: progress reaches the dialog, Cancel stops the job,
// errors come back with their hint, and the GUI thread stays responsive meanwhile.
#include <atomic>
#include <chrono>
#include <thread>

// Before Qt: its `emit` macro breaks TBB's profiling header.
#include <tbb/parallel_for.h>

#include <QApplication>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QWidget>

#include <gtest/gtest.h>

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/ui/jobs/background_priority.h"
#include "spira/ui/jobs/task_runner.h"

namespace spira::test {
namespace {

using spira::ui::TaskOutcome;
using spira::ui::TaskRunner;

TaskOutcome runAndWait(TaskRunner& runner, TaskRunner::Job job)
{
  TaskOutcome result;
  bool called = false;
  EXPECT_TRUE(runner.start("Test", std::move(job), [&](const TaskOutcome& o) {
    result = o;
    called = true;
  }));
  runner.waitForFinished();
  EXPECT_TRUE(called);
  EXPECT_FALSE(runner.busy());
  return result;
}

// Jobs run below the GUI thread's priority, their TBB workers too, so a plan using every core
// leaves the event loop its share; the GUI thread itself keeps its own priority.
TEST(TaskRunner, JobsAndTheirParallelWorkersYieldToTheGuiThread)
{
  QWidget parent;
  TaskRunner runner(&parent);
  const int guiNice = ui::BackgroundPriority::currentNice();
  std::atomic<int> jobNice{-100}, lowestWorkerNice{100};
  std::atomic<int> otherThreads{0};
  TaskOutcome o = runAndWait(runner, [&](Progress&) {
    jobNice = ui::BackgroundPriority::currentNice();
    const std::thread::id self = std::this_thread::get_id();
    // Enough slow iterations that the workers join in.
    tbb::parallel_for(0, 64, [&](int) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      if (std::this_thread::get_id() == self) return;
      ++otherThreads;
      int seen = lowestWorkerNice.load();
      const int nice = ui::BackgroundPriority::currentNice();
      while (nice < seen && !lowestWorkerNice.compare_exchange_weak(seen, nice)) {
      }
    });
  });
  ASSERT_TRUE(o.succeeded());
  EXPECT_GE(jobNice.load(), ui::BackgroundPriority::kNice);
  // TBB has workers wherever there is more than one core.
  if (std::thread::hardware_concurrency() > 1) {
    EXPECT_GT(otherThreads.load(), 0);
  }
  if (otherThreads > 0) {
    EXPECT_GE(lowestWorkerNice.load(), ui::BackgroundPriority::kNice);
  }
  EXPECT_EQ(ui::BackgroundPriority::currentNice(), guiNice);
  EXPECT_LT(guiNice, ui::BackgroundPriority::kNice);
}

TEST(TaskRunner, ReturnsErrorsWithTheirHint)
{
  QWidget parent;
  TaskRunner runner(&parent);
  TaskOutcome o =
      runAndWait(runner, [](Progress&) { throw InputError("the file is truncated", "export it again"); });
  EXPECT_EQ(o.status, TaskOutcome::Status::Failed);
  EXPECT_EQ(o.message, "the file is truncated");
  EXPECT_EQ(o.hint, "export it again");

  o = runAndWait(runner, [](Progress&) { throw std::runtime_error("index out of range"); });
  EXPECT_EQ(o.status, TaskOutcome::Status::Failed);
  EXPECT_TRUE(o.message.contains("index out of range"));
  EXPECT_FALSE(o.hint.isEmpty());

  // Spira's own broken invariant is a bug, never shown as a problem with the user's input.
  o = runAndWait(runner, [](Progress&) { throw InternalError("spiral has no revolutions", "unused hint"); });
  EXPECT_EQ(o.status, TaskOutcome::Status::Failed);
  EXPECT_EQ(o.message, "Internal error: spiral has no revolutions");
  EXPECT_TRUE(o.hint.contains("bug in Spira")) << o.hint.toStdString();

  int value = 0;
  o = runAndWait(runner, [&value](Progress& p) {
    p.report(1.0, "done");
    value = 42;
  });
  EXPECT_TRUE(o.succeeded());
  EXPECT_EQ(value, 42);
}

TEST(TaskRunner, ProgressDialogShowsTheStageAndItsCancelStopsTheJob)
{
  QWidget parent;
  parent.resize(400, 300);
  parent.show();
  TaskRunner runner(&parent);
  QSignalSpy finished(&runner, &TaskRunner::finished);
  std::atomic<int> loops{0};
  ASSERT_TRUE(runner.start("Long job", [&loops](Progress& p) {
    for (;;) {
      p.report(0.25, "Reading STL");
      p.checkCancel();
      ++loops;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }));
  EXPECT_TRUE(runner.busy());
  EXPECT_FALSE(runner.start("Second", [](Progress&) {}));  // one job at a time

  // The dialog appears once the job has run for a moment, showing the job's own words.
  QProgressDialog* dialog = nullptr;
  for (int i = 0; i < 200 && !(dialog && dialog->isVisible()); ++i) {
    QApplication::processEvents(QEventLoop::AllEvents, 10);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    dialog = parent.findChild<QProgressDialog*>();
  }
  ASSERT_NE(dialog, nullptr);
  ASSERT_TRUE(dialog->isVisible());
  for (int i = 0; i < 20; ++i) QApplication::processEvents(QEventLoop::AllEvents, 10);
  EXPECT_EQ(dialog->labelText(), "Long job\nReading STL");
  EXPECT_EQ(dialog->value(), 250);
  EXPECT_GT(loops.load(), 0);
  EXPECT_TRUE(finished.isEmpty());

  QPushButton* cancel = dialog->findChild<QPushButton*>();
  ASSERT_NE(cancel, nullptr);
  EXPECT_EQ(cancel->text(), "Cancel");
  cancel->click();
  ASSERT_TRUE(finished.wait(10000));
  EXPECT_EQ(finished.at(0).at(0).value<TaskOutcome>().status, TaskOutcome::Status::Cancelled);
  EXPECT_FALSE(runner.busy());
}

}  // namespace
}  // namespace spira::test
