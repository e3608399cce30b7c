#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "spira/path/trajectory.h"

namespace spira {

// The project file's form of a trajectory (results_codec.cpp): one binary blob per channel.
nlohmann::json trajectoryToJson(const Trajectory& t);
Trajectory trajectoryFromJson(const nlohmann::json& j, const std::string& what);  // InputError

}  // namespace spira
