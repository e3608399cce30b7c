#include "py_options.h"

#include "py_errors.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace py = pybind11;

namespace spira::python {
namespace {

bool isNumber(py::handle v)
{
  return !py::isinstance<py::bool_>(v) && (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v));
}
bool isInteger(py::handle v)
{
  return !py::isinstance<py::bool_>(v) && py::isinstance<py::int_>(v);
}

}  // namespace

std::string pathArgument(const char* function, const std::string& name, py::handle value)
{
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::hasattr(value, "__fspath__")) {
    const py::object text = value.attr("__fspath__")();
    if (py::isinstance<py::str>(text)) return text.cast<std::string>();
  }
  raiseTypeError(function, name, "a path (str or os.PathLike)", value);
}

Options::Options(const char* function, const py::kwargs& kwargs) : function_(function)
{
  for (const auto& [key, value] : kwargs)
    values_[key.cast<std::string>()] = py::reinterpret_borrow<py::object>(value);
}

py::object Options::take(const std::string& name)
{
  const auto it = values_.find(name);
  if (it == values_.end()) return py::none();
  py::object v = std::move(it->second);
  values_.erase(it);
  return v;
}

std::optional<bool> Options::takeBool(const std::string& name)
{
  const py::object v = take(name);
  if (v.is_none()) return std::nullopt;
  if (!py::isinstance<py::bool_>(v)) raiseTypeError(function_, name, "bool", v);
  return v.cast<bool>();
}

std::optional<double> Options::takeNumber(const std::string& name)
{
  const py::object v = take(name);
  if (v.is_none()) return std::nullopt;
  if (!isNumber(v)) raiseTypeError(function_, name, "a number", v);
  return v.cast<double>();
}

std::optional<long long> Options::takeInteger(const std::string& name)
{
  const py::object v = take(name);
  if (v.is_none()) return std::nullopt;
  if (!isInteger(v)) raiseTypeError(function_, name, "int", v);
  return v.cast<long long>();
}

std::optional<std::string> Options::takeText(const std::string& name)
{
  const py::object v = take(name);
  if (v.is_none()) return std::nullopt;
  if (!py::isinstance<py::str>(v)) raiseTypeError(function_, name, "str", v);
  return v.cast<std::string>();
}

std::optional<std::string> Options::takePath(const std::string& name)
{
  const py::object v = take(name);
  if (v.is_none()) return std::nullopt;
  return pathArgument(function_, name, v);
}

void Options::setParameter(const std::vector<const FlagTarget*>& targets, const std::string& key,
                           py::handle value, const std::string& argument) const
{
  const ParamDef& def = *targets.front()->schema->find(key);
  // The value as the CLI's flag would spell it, so that it is parsed and checked as the flag is.
  std::string text;
  switch (def.type) {
    case ParamType::Bool:
      if (!py::isinstance<py::bool_>(value)) raiseTypeError(function_, argument, "bool", value);
      text = value.cast<bool>() ? "true" : "false";
      break;
    case ParamType::Int:
      if (!isInteger(value)) raiseTypeError(function_, argument, "int", value);
      text = std::to_string(value.cast<long long>());
      break;
    case ParamType::Double:
      if (!isNumber(value)) raiseTypeError(function_, argument, "a number", value);
      appendNumber(text, value.cast<double>());  // the shortest text that reads back to the same double
      break;
    case ParamType::Path:
      text = pathArgument(function_, argument, value);
      break;
    case ParamType::String:
    case ParamType::Choice:
      if (!py::isinstance<py::str>(value)) raiseTypeError(function_, argument, "str", value);
      text = value.cast<std::string>();
      break;
  }
  try {
    for (const FlagTarget* t : targets) t->values->set(key, t->schema->parse(key, text));
  } catch (const InputError& e) {
    throw UsageError(e.what(), e.hint());  // as the CLI's takeParamFlags reports a bad flag value
  }
}

void Options::takeSettings(const std::vector<FlagTarget>& targets)
{
  const auto declaring = [&](const std::string& key) {
    std::vector<const FlagTarget*> found;
    for (const FlagTarget& t : targets)
      if (t.schema->find(key)) found.push_back(&t);
    return found;
  };
  const auto setFlat = [&](const std::string& key, py::handle value, const std::string& argument) {
    const auto found = declaring(key);
    if (found.empty())
      throw py::type_error(std::string(function_) + "() got an unexpected keyword argument '" + key + "'");
    setParameter(found, key, value, argument);
  };

  const py::object settings = take("settings");
  if (!settings.is_none()) {
    if (!py::isinstance<py::dict>(settings)) raiseTypeError(function_, "settings", "a dict", settings);
    for (const auto& [k, v] : settings.cast<py::dict>()) {
      if (!py::isinstance<py::str>(k)) raiseTypeError(function_, "settings key", "str", k);
      const std::string key = k.cast<std::string>();
      const FlagTarget* owner = nullptr;
      for (const FlagTarget& t : targets)
        if (t.owner == key) owner = &t;
      if (!owner) {
        setFlat(key, v, key);
        continue;
      }
      if (!py::isinstance<py::dict>(v)) raiseTypeError(function_, "settings['" + key + "']", "a dict", v);
      for (const auto& [ik, iv] : v.cast<py::dict>()) {
        const std::string inner = py::str(ik);
        if (!py::isinstance<py::str>(ik) || !owner->schema->find(inner))
          throw py::type_error(std::string(function_) + "() got an unexpected keyword argument '" + inner +
                               "' in settings['" + key + "']");
        setParameter({owner}, inner, iv, inner);
      }
    }
  }
  for (auto it = values_.begin(); it != values_.end();) {
    if (declaring(it->first).empty()) {
      ++it;
      continue;
    }
    setFlat(it->first, it->second, it->first);
    it = values_.erase(it);
  }
}

void Options::finish() const
{
  if (!values_.empty())
    throw py::type_error(std::string(function_) + "() got an unexpected keyword argument '" +
                         values_.begin()->first + "'");
}

}  // namespace spira::python
