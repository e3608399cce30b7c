#pragma once

#include "spira/path/trajectory.h"

namespace spira {

// The plane (z, mm) the first revolution rests on: each of its points lies its deposit height above
// it, along the point's build direction. What the shell's first row is joined to when the plan does
// not say where the plate is.
double substratePlaneOf(const Trajectory& t);

}  // namespace spira
