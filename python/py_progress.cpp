#include "py_progress.h"

namespace py = pybind11;

namespace spira::python {

PythonProgress::PythonProgress(const char* function, py::object callback) : callback_(std::move(callback))
{
  if (!callback_.is_none() && !PyCallable_Check(callback_.ptr()))
    raiseTypeError(function, "progress", "a callable(fraction, stage) or None", callback_);
}

PythonProgress::~PythonProgress() = default;

void PythonProgress::report(double fraction, std::string_view stage)
{
  // After a cancel the work still reports until it next checks; the callback has had its answer.
  if (cancelled()) return;
  py::gil_scoped_acquire gil;
  // With the GIL released Python runs no signal handler: Ctrl-C would wait for the end of the work.
  if (PyErr_CheckSignals() != 0) {
    interrupt_ = std::make_unique<py::error_already_set>();
    cancel_.store(true, std::memory_order_relaxed);
    return;
  }
  if (callback_.is_none()) return;
  try {
    const py::object answer = callback_(fraction, py::str(stage.data(), stage.size()));
    if (answer.is(py::bool_(false))) cancel_.store(true, std::memory_order_relaxed);
  } catch (py::error_already_set& e) {
    if (!error_) error_ = std::make_unique<py::error_already_set>(std::move(e));
    cancel_.store(true, std::memory_order_relaxed);
  }
}

void PythonProgress::raiseStopped()
{
  if (interrupt_) {
    interrupt_->restore();
    throw py::error_already_set();
  }
  raiseCancelled(error_.get());
}

}  // namespace spira::python
