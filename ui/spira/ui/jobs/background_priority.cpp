#include "spira/ui/jobs/background_priority.h"

#include <tbb/task_scheduler_observer.h>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#endif

namespace spira::ui {

namespace {

void lowerThisThread()
{
#if defined(__linux__)
  // Linux keeps a nice value per thread: PRIO_PROCESS with a thread id changes only that thread.
  const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
  if (BackgroundPriority::currentNice() < BackgroundPriority::kNice)
    ::setpriority(PRIO_PROCESS, tid, BackgroundPriority::kNice);
#endif
}

}  // namespace

// Workers are shared by all arenas; the default observer hears those entering the arena of the
// thread that calls observe(), i.e. the background job's own parallel loops.
struct BackgroundPriority::Observer : tbb::task_scheduler_observer {
  Observer() { observe(true); }
  ~Observer() override { observe(false); }
  void on_scheduler_entry(bool isWorker) override
  {
    if (isWorker) lowerThisThread();
  }
};

BackgroundPriority::BackgroundPriority()
{
  lowerThisThread();
  observer_ = std::make_unique<Observer>();
}

BackgroundPriority::~BackgroundPriority() = default;

int BackgroundPriority::currentNice()
{
#if defined(__linux__)
  errno = 0;
  const int nice = ::getpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)));
  return errno == 0 ? nice : 0;
#else
  return 0;
#endif
}

}  // namespace spira::ui
