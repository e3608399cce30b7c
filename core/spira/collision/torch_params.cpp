#include "spira/collision/torch_params.h"

#include <cmath>
#include <string>

#include "spira/base/error.h"

namespace spira {

namespace {

void requireNonNegative(double value, const char* name)
{
  if (!std::isfinite(value) || value < 0.0)
    throw InputError(std::string("torch ") + name + " is " + std::to_string(value) + " mm",
                     "give a finite length of zero or more");
}

}  // namespace

void validateTorchParams(const TorchParams& p)
{
  requireNonNegative(p.nozzleRadius, "nozzle radius");
  requireNonNegative(p.coneLength, "cone length");
  requireNonNegative(p.bodyRadius, "body radius");
  requireNonNegative(p.bodyLength, "body length");
  requireNonNegative(p.standoff, "standoff");
  requireNonNegative(p.clearance, "clearance");
  if (p.nozzleRadius > p.bodyRadius)
    throw InputError("torch nozzle radius " + std::to_string(p.nozzleRadius) +
                         " mm exceeds the body radius " + std::to_string(p.bodyRadius) + " mm",
                     "the nozzle tapers towards the tip: give a body radius at least the nozzle radius");
  if (p.coneLength + p.bodyLength <= 0.0)
    throw InputError("the torch has zero length", "give a cone or body length above zero");
}

}  // namespace spira
