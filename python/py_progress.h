#pragma once

#include <atomic>
#include <memory>
#include <utility>

#include <pybind11/pybind11.h>

#include "py_errors.h"
#include "spira/base/progress.h"

namespace spira::python {

// Spira's Progress for a Python callback(fraction, stage): called with the GIL held, from whichever
// thread reports; returning False or raising cancels the work. Each report also lets Python handle its
// signals, so that Ctrl-C stops the work with KeyboardInterrupt.
class PythonProgress final : public Progress {
 public:
  // `callback`: None or a callable; anything else is a TypeError naming `function`'s argument.
  PythonProgress(const char* function, pybind11::object callback);
  ~PythonProgress() override;
  void report(double fraction, std::string_view stage) override;
  bool cancelled() const override { return cancel_.load(std::memory_order_relaxed); }

  // Runs `work` with the GIL released; a cancelled run raises spira.Cancelled (from the callback's
  // exception when it raised one), an interrupted one the KeyboardInterrupt.
  template <class Work>
  auto run(Work&& work)
  {
    try {
      pybind11::gil_scoped_release release;
      return std::forward<Work>(work)();
    } catch (const Cancelled&) {
      raiseStopped();
    }
  }

 private:
  [[noreturn]] void raiseStopped();

  pybind11::object callback_;
  std::atomic<bool> cancel_{false};
  std::unique_ptr<pybind11::error_already_set> error_;      // what the callback raised
  std::unique_ptr<pybind11::error_already_set> interrupt_;  // what a signal handler raised
};

}  // namespace spira::python
