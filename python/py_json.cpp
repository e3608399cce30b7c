#include "py_json.h"

#include <nlohmann/json.hpp>

namespace py = pybind11;

namespace spira::python {

py::object toPython(const nlohmann::json& value)
{
  // Through the text: the numbers read back exactly, and Python gets the types its json module gives.
  return py::module_::import("json").attr("loads")(value.dump());
}

}  // namespace spira::python
