#pragma once

#include <stdexcept>
#include <string>

#include <pybind11/pybind11.h>

namespace spira::python {

// What the CLI calls a usage error (exit code 2): an option of the wrong value, one that contradicts
// another. Raised in Python as spira.UsageError, a ValueError.
class UsageError : public std::runtime_error {
 public:
  UsageError(const std::string& what, std::string hint) : std::runtime_error(what), hint_(std::move(hint)) {}
  const std::string& hint() const { return hint_; }

 private:
  std::string hint_;
};

// Declares spira.Error and its kinds, spira.UsageError and spira.Cancelled on `m`, and translates
// Spira's C++ errors into them: str(e) is the line spira-cli prints after "spira-cli: ", e.hint the
// hint alone, e.exit_code the CLI's exit code.
void bindErrors(pybind11::module_& m);

// spira.Cancelled raised from `cause` (an exception the progress callback raised), or alone when
// `cause` is null.
[[noreturn]] void raiseCancelled(pybind11::error_already_set* cause);

// TypeError "FUNCTION(): argument 'NAME' must be EXPECTED, not TYPE".
[[noreturn]] void raiseTypeError(const std::string& function, const std::string& name,
                                 const std::string& expected, pybind11::handle got);

}  // namespace spira::python
