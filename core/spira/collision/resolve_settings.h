#pragma once

#include "spira/base/units.h"

namespace spira {

// How torch conflicts are resolved by tilting about the travel direction t (thesis 4.3.2: keep the
// TCP, rotate the torch about t until it clears, add a safety angle). Angles in radians.
struct ResolveSettings {
  double searchStepRad = degToRad(2.0);     // increments of the scan for the first clear angle
  double toleranceRad = degToRad(0.05);     // bisection stops when the bracket is this narrow
  double safetyAngleRad = degToRad(5.0);    // added to the smallest clearing angle (deposit variation)
  double maxTiltRad = degToRad(45.0);       // no tilt beyond this; a point needing more is unresolved
  double maxTiltChangeRad = degToRad(1.0);  // largest tilt change between consecutive points (ramps)
  int maxPasses = 8;                        // re-checks of ramped points that collide in turn
};

// Throws InputError naming the first bad field.
void validateResolveSettings(const ResolveSettings& settings);

}  // namespace spira
