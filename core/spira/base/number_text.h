#pragma once

#include <optional>
#include <string>
#include <string_view>

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
// At most `decimals` after the decimal point, without trailing zeros ("2.5", "120", "0.004"), in the
// shortest form that reads back to the rounded value: a value a user may type back.
std::string roundedText(double x, int decimals);
// `x` rounded to `decimals` places, as a controller reads it back from a program's text.
double roundedTo(double x, int decimals);
// "(x, y, z)" with `digits` after each decimal point: a position in a message.
std::string pointText(const Vec3& p, int digits);

// The whole of `text` read as a finite decimal number (an optional leading '+', no spaces, the same
// in every locale), or nullopt with `problem` set to what is wrong, worded to follow the quoted text:
// "is not a number", "is beyond the range of a double", "is not a finite number". A denormal such as
// 4.9e-324 is a number.
std::optional<double> parseFiniteNumber(std::string_view text, std::string& problem);
// The same for a whole number ("3.7", "1e3" are not one).
std::optional<long long> parseWholeNumber(std::string_view text, std::string& problem);

// A coordinate as mesh files (STL, PLY) write it: `text` whole, an optional leading '+'. A value
// beyond a double reads as an infinity of its sign, so that the import reports it with the other
// non-finite coordinates, and one below the smallest denormal as 0; nullopt when it is not a number.
std::optional<double> parseMeshNumber(std::string_view text);

// User text quoted in a message, clipped to about 60 characters with an ellipsis so that a huge
// value is not echoed back.
std::string clippedText(std::string_view text);

}  // namespace spira
