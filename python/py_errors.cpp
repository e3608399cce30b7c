#include "py_errors.h"

#include "spira/base/error.h"
#include "spira/base/exit_code.h"
#include "spira/base/progress.h"

namespace py = pybind11;

namespace spira::python {
namespace {

// The classes live as long as the interpreter: the module holds a reference to each.
struct ErrorTypes {
  PyObject* error = nullptr;
  PyObject* input = nullptr;
  PyObject* usage = nullptr;
  PyObject* io = nullptr;
  PyObject* algorithm = nullptr;
  PyObject* infeasible = nullptr;
  PyObject* internal = nullptr;
  PyObject* cancelled = nullptr;
};
ErrorTypes types;

PyObject* newType(py::module_& m, const char* name, py::tuple bases, const char* doc)
{
  const std::string qualified = std::string("spira.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!type) throw py::error_already_set();
  m.add_object(name, py::handle(type));
  return type;
}

void setError(PyObject* type, const std::string& message, const std::string& what, const std::string& hint,
              int exitCode)
{
  py::object e = py::reinterpret_borrow<py::object>(type)(message);
  e.attr("message") = what;
  e.attr("hint") = hint;
  e.attr("exit_code") = exitCode;
  PyErr_SetObject(type, e.ptr());
}

void translate(std::exception_ptr p)
{
  if (!p) return;
  const Failure failure = failureOf(p);
  try {
    std::rethrow_exception(p);
  } catch (const UsageError& e) {
    setError(types.usage, std::string(e.what()) + " (" + e.hint() + ")", e.what(), e.hint(), kExitUsage);
  } catch (const Cancelled&) {
    PyErr_SetString(types.cancelled, Cancelled().what());
  } catch (const Error& e) {
    PyObject* type = dynamic_cast<const InfeasibleError*>(&e)  ? types.infeasible
                     : dynamic_cast<const InputError*>(&e)     ? types.input
                     : dynamic_cast<const IoError*>(&e)        ? types.io
                     : dynamic_cast<const AlgorithmError*>(&e) ? types.algorithm
                                                               : types.internal;
    setError(type, failure.message, e.what(), e.hint(), failure.exitCode);
  }
  // Anything else (std::bad_alloc, a foreign std::exception) leaves this translator uncaught, which
  // tells pybind11 to try its own.
}

}  // namespace

void bindErrors(py::module_& m)
{
  const py::handle runtime(PyExc_RuntimeError), value(PyExc_ValueError), os(PyExc_OSError);
  types.error = newType(m, "Error", py::make_tuple(runtime), "Every error Spira raises (but Cancelled).");
  const py::handle error(types.error);
  types.input = newType(m, "InputError", py::make_tuple(error, value),
                        "Input the user can fix: a bad mesh, an unsupported file, a value out of range.");
  types.usage =
      newType(m, "UsageError", py::make_tuple(error, value),
              "Options that do not fit together or a setting of the wrong value (the CLI's exit code 2).");
  types.io = newType(m, "IoError", py::make_tuple(error, os), "A file could not be read or written.");
  types.algorithm = newType(m, "AlgorithmError", py::make_tuple(error),
                            "Spira could not plan this valid input (no solution, no convergence).");
  types.infeasible = newType(m, "InfeasibleError", py::make_tuple(error),
                             "The plan violates the process window or the cell's limits.");
  types.internal = newType(m, "InternalError", py::make_tuple(error), "A bug in Spira: please report it.");
  types.cancelled = newType(m, "Cancelled", py::make_tuple(py::handle(PyExc_Exception)),
                            "The progress callback returned False or raised: the work stopped.");
  py::register_exception_translator(&translate);
}

void raiseCancelled(py::error_already_set* cause)
{
  if (cause)
    py::raise_from(*cause, types.cancelled, Cancelled().what());
  else
    PyErr_SetString(types.cancelled, Cancelled().what());
  throw py::error_already_set();
}

void raiseTypeError(const std::string& function, const std::string& name, const std::string& expected,
                    py::handle got)
{
  const std::string type = py::str(py::type::handle_of(got).attr("__name__"));
  throw py::type_error(function + "(): argument '" + name + "' must be " + expected + ", not " + type);
}

}  // namespace spira::python
