#include "spira/base/units.h"

namespace spira {

double millimetresPer(LengthUnit unit)
{
  switch (unit) {
    case LengthUnit::Millimetre:
      return 1.0;
    case LengthUnit::Centimetre:
      return 10.0;
    case LengthUnit::Metre:
      return 1000.0;
    case LengthUnit::Inch:
      return 25.4;
    case LengthUnit::Foot:
      return 304.8;
    case LengthUnit::Micrometre:
      return 1e-3;
  }
  return 1.0;
}

std::string_view lengthUnitSymbol(LengthUnit unit)
{
  switch (unit) {
    case LengthUnit::Millimetre:
      return "mm";
    case LengthUnit::Centimetre:
      return "cm";
    case LengthUnit::Metre:
      return "m";
    case LengthUnit::Inch:
      return "in";
    case LengthUnit::Foot:
      return "ft";
    case LengthUnit::Micrometre:
      return "um";
  }
  return "mm";
}

std::optional<LengthUnit> parseLengthUnit(std::string_view s)
{
  if (s == "mm") return LengthUnit::Millimetre;
  if (s == "cm") return LengthUnit::Centimetre;
  if (s == "m") return LengthUnit::Metre;
  if (s == "in" || s == "inch") return LengthUnit::Inch;
  if (s == "ft" || s == "foot") return LengthUnit::Foot;
  if (s == "um") return LengthUnit::Micrometre;
  return std::nullopt;
}

double toInternalFactor(std::string_view unit)
{
  if (unit == "deg" || unit == "deg/s") return kPi / 180.0;
  if (unit == "m/min") return 1000.0 / 60.0;  // -> mm/s
  if (unit == "mm/min") return 1.0 / 60.0;    // -> mm/s
  if (unit == "m/s") return 1000.0;           // -> mm/s
  if (unit == "m") return 1000.0;
  if (unit == "cm") return 10.0;
  if (unit == "%") return 0.01;
  if (unit == "ms") return 1e-3;
  return 1.0;
}

}  // namespace spira
