#pragma once

#include <pybind11/pybind11.h>
#include <nlohmann/json_fwd.hpp>

namespace spira::python {

// A JSON value as Python's json module reads it (dict, list, float...): the report.json text, read back.
pybind11::object toPython(const nlohmann::json& value);

}  // namespace spira::python
