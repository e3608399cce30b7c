#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace spira {

// Internal units are millimetres, radians and seconds. Files and the UI may use others;
// conversion happens once, at the edge, through these helpers.
constexpr double kPi = 3.14159265358979323846;
constexpr double degToRad(double deg)
{
  return deg * kPi / 180.0;
}
constexpr double radToDeg(double rad)
{
  return rad * 180.0 / kPi;
}

enum class LengthUnit { Millimetre, Centimetre, Metre, Inch, Foot, Micrometre };

// Millimetres per one `unit`.
double millimetresPer(LengthUnit unit);
std::string_view lengthUnitSymbol(LengthUnit unit);
std::optional<LengthUnit> parseLengthUnit(std::string_view symbol);

// Factor that converts a value written in `unit` (a parameter-schema unit such as "deg",
// "m/min", "mm/s", "mm", "%") into Spira's internal units. Unknown or empty units give 1.
double toInternalFactor(std::string_view unit);

}  // namespace spira
