#pragma once

#include <string>

namespace spira {

// Appends the shortest decimal text that reads back to exactly `x` (std::to_chars), the form
// every text file Spira writes uses, so CSV/OBJ/PLY/VTP round trips are bit-for-bit.
void appendNumber(std::string& out, double x);
void appendNumber(std::string& out, long long x);

}  // namespace spira
