#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

namespace spira::test {

// resources/cells/`name` rewritten into `dir` under the same name: its URDF paths made absolute
// (they are relative to the cell file), then `edit` applied to its JSON. Returns the new file.
std::filesystem::path bundledCellVariant(const std::string& name, const std::filesystem::path& dir,
                                         const std::function<void(nlohmann::json&)>& edit);

// An open cylinder of radius `r` and `height` mm (2 mm edges) written to dir/cylinder.stl.
std::filesystem::path cylinderPart(const std::filesystem::path& dir, double r, double height);

}  // namespace spira::test
