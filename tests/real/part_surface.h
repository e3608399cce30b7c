#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "real/deposit_check.h"

namespace spira::test::real {

// The part's triangles in millimetres, for the coverage figures. STL is read here (binary or
// ASCII) so the check depends on nothing of the product; other formats go through Spira's own
// importer, the one product part the check uses. `unit` is the file's length unit: mm, cm, m, in.
std::vector<Triangle> readPartSurface(const std::filesystem::path& file, const std::string& unit);

// Millimetres per one `unit` (mm, cm, m, in); throws std::invalid_argument for anything else.
double millimetresPer(const std::string& unit);

}  // namespace spira::test::real
