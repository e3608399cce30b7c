#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <string_view>

namespace spira {

// Thrown by Progress::checkCancel() when the user cancelled. Not a spira::Error: callers that
// catch errors to show them must let this one through.
class Cancelled : public std::exception {
 public:
  const char* what() const noexcept override { return "cancelled by the user"; }
};

// How long work reports progress and learns that it should stop. Algorithms call
// `report()` now and then and `checkCancel()` inside every loop that may run long.
class Progress {
 public:
  virtual ~Progress() = default;
  // fraction in [0, 1] of the current stage; stage is a short human-readable name.
  virtual void report(double fraction, std::string_view stage) = 0;
  virtual bool cancelled() const = 0;
  void checkCancel() const
  {
    if (cancelled()) throw Cancelled();
  }
};

// Reports nothing and is never cancelled.
class NullProgress final : public Progress {
 public:
  void report(double, std::string_view) override {}
  bool cancelled() const override { return false; }
};

// Forwards to a callback; cancellation through an atomic flag another thread may set.
class CallbackProgress final : public Progress {
 public:
  using Callback = std::function<void(double, std::string_view)>;
  explicit CallbackProgress(Callback cb = {}) : cb_(std::move(cb)) {}
  void report(double fraction, std::string_view stage) override
  {
    if (cb_) cb_(fraction, stage);
  }
  bool cancelled() const override { return cancel_.load(std::memory_order_relaxed); }
  void cancel() { cancel_.store(true, std::memory_order_relaxed); }

 private:
  Callback cb_;
  std::atomic<bool> cancel_{false};
};

// Maps a sub-task's [0,1] onto [begin, end] of a parent's progress, with its own stage name.
class SubProgress final : public Progress {
 public:
  SubProgress(Progress& parent, double begin, double end, std::string stage)
      : parent_(parent), begin_(begin), end_(end), stage_(std::move(stage))
  {
  }
  void report(double fraction, std::string_view stage) override
  {
    parent_.report(begin_ + (end_ - begin_) * fraction, stage.empty() ? std::string_view(stage_) : stage);
  }
  bool cancelled() const override { return parent_.cancelled(); }

 private:
  Progress& parent_;
  double begin_, end_;
  std::string stage_;
};

}  // namespace spira
