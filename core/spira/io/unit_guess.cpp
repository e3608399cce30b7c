#include "spira/io/unit_guess.h"

#include <algorithm>

#include "spira/base/number_text.h"

namespace spira {
namespace {

// Below this a part is smaller than the narrowest wall a WAAM torch can build around.
constexpr double kSmallestPartMm = 20.0;
// Below this, metres are more likely than centimetres or inches (a 3 m part read as 3 mm).
constexpr double kMetreSuspectMm = 3.0;
// Beyond this no WAAM cell holds the part: micrometres or a CAD unit mismatch.
constexpr double kLargestPartMm = 20000.0;

std::string mm(double v)
{
  return fixedText(v, v < 10.0 ? 2 : 0);
}

}  // namespace

std::optional<std::string> unitWarning(const BoundingBox& bounds, LengthUnit read)
{
  if (bounds.empty()) return std::nullopt;
  const double size = bounds.size().maxCoeff();
  if (!(size > 0.0)) return std::nullopt;
  const std::string asRead = "the part is " + mm(size) + " mm across as read (file unit " +
                             std::string(lengthUnitSymbol(read)) + ")";
  if (size < kMetreSuspectMm && read != LengthUnit::Metre)
    return asRead + ", too small for a WAAM part: the file is probably in metres (" + mm(size * 1000.0) +
           " mm); import it with --unit m";
  if (size < kSmallestPartMm && read == LengthUnit::Millimetre)
    return asRead + ", too small for a WAAM part: if the file is in inches (" + mm(size * 25.4) +
           " mm) import it with --unit in, if in centimetres (" + mm(size * 10.0) + " mm) with --unit cm";
  if (size > kLargestPartMm && read != LengthUnit::Millimetre)
    return asRead + ", larger than any WAAM cell: if the file is in millimetres (" +
           mm(size / millimetresPer(read)) + " mm) import it with --unit mm";
  return std::nullopt;
}

}  // namespace spira
