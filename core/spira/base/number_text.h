#pragma once

#include <string>

#include "spira/base/transform.h"

namespace spira {

// Appends the shortest decimal text that reads back to exactly `x` (std::to_chars), the form
// every text file Spira writes uses, so CSV/OBJ/PLY/VTP round trips are bit-for-bit.
void appendNumber(std::string& out, double x);
void appendNumber(std::string& out, long long x);

// Text for messages: `digits` after the decimal point ("2.45"), or `digits` significant ones
// ("1.55", "120.5"), as a reader of a message wants them rather than bit-exact.
std::string fixedText(double x, int digits);
std::string significantText(double x, int digits);
// "(x, y, z)" with `digits` after each decimal point: a position in a message.
std::string pointText(const Vec3& p, int digits);

}  // namespace spira
