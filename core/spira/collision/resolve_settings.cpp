#include "spira/collision/resolve_settings.h"

#include <cmath>
#include <string>

#include "spira/base/error.h"

namespace spira {

namespace {

void requirePositiveAngle(double value, const char* name, bool allowZero = false)
{
  const bool ok = std::isfinite(value) && (allowZero ? value >= 0.0 : value > 0.0) && value <= kPi / 2.0;
  if (!ok)
    throw InputError(
        std::string("collision resolution: ") + name + " is " + std::to_string(radToDeg(value)) + " deg",
        allowZero ? "give an angle between 0 and 90 deg" : "give an angle above 0 and up to 90 deg");
}

}  // namespace

void validateResolveSettings(const ResolveSettings& s)
{
  requirePositiveAngle(s.searchStepRad, "search step");
  requirePositiveAngle(s.toleranceRad, "angle tolerance");
  requirePositiveAngle(s.safetyAngleRad, "safety angle", true);
  requirePositiveAngle(s.maxTiltRad, "maximum tilt");
  requirePositiveAngle(s.maxTiltChangeRad, "maximum tilt change per point");
  if (s.maxPasses < 1)
    throw InputError("collision resolution: " + std::to_string(s.maxPasses) + " passes",
                     "give one pass or more");
}

}  // namespace spira
