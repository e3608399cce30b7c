#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "spira/plugin/param_cli.h"

namespace spira::python {

// The keyword arguments of one API function, taken one by one as the CLI takes its flags: a value of
// the wrong Python type is a TypeError naming the argument, a bad value the CLI's error.
class Options {
 public:
  Options(const char* function, const pybind11::kwargs& kwargs);

  const char* function() const { return function_; }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  // The argument removed, or None when absent.
  pybind11::object take(const std::string& name);
  std::optional<bool> takeBool(const std::string& name);
  std::optional<double> takeNumber(const std::string& name);
  std::optional<long long> takeInteger(const std::string& name);
  std::optional<std::string> takeText(const std::string& name);
  // A str or an os.PathLike, as text.
  std::optional<std::string> takePath(const std::string& name);

  // The setting arguments: each remaining keyword names a parameter of one or more `targets` (all of
  // them set, as a CLI flag sets every section it names), and `settings`, when given, is a dict of
  // the same keys, or of a target's name (section or plugin id) to a dict of its own keys.
  void takeSettings(const std::vector<FlagTarget>& targets);
  // TypeError naming the first argument nothing took.
  void finish() const;

 private:
  void setParameter(const std::vector<const FlagTarget*>& targets, const std::string& key,
                    pybind11::handle value, const std::string& argument) const;

  const char* function_;
  std::map<std::string, pybind11::object> values_;
};

// `value` as a path (str or os.PathLike) for `function`'s argument `name`.
std::string pathArgument(const char* function, const std::string& name, pybind11::handle value);

}  // namespace spira::python
