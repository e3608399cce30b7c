#pragma once

#include <memory>

namespace spira::ui {

// Lowers the scheduling priority of the calling thread and of every TBB worker that joins its
// work, for as long as the object lives on that thread. Background jobs (plans, exports) then
// take only the CPU time the GUI thread leaves: on a 2-core machine an un-niced plan using both
// cores starves the event loop for 100-200 ms at a time.
//
// Lowering is one-way for an unprivileged process (RLIMIT_NICE), so workers stay at the lower
// priority afterwards; the GUI thread itself is never touched. On platforms without per-thread
// nice values this does nothing.
class BackgroundPriority {
 public:
  BackgroundPriority();
  ~BackgroundPriority();
  BackgroundPriority(const BackgroundPriority&) = delete;
  BackgroundPriority& operator=(const BackgroundPriority&) = delete;

  // The nice value background threads run at (0 normal, 19 lowest). 5 gives the GUI thread
  // three quarters of a contended core; 10 slowed plans up to ninefold on a machine busy with
  // other programs, for little extra smoothness.
  static constexpr int kNice = 5;

  // The calling thread's nice value, or 0 where it cannot be read.
  static int currentNice();

 private:
  struct Observer;
  std::unique_ptr<Observer> observer_;
};

}  // namespace spira::ui
