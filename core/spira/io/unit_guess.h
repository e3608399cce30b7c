#pragma once

#include <optional>
#include <string>

#include "spira/base/units.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// WAAM parts are a few centimetres to a few metres across; a bead ring alone is about 15 mm round.
// A part outside that range was most likely read in the wrong unit: returns what it would measure
// in the likely unit and the import flag that reads it so, or nothing when the size is plausible.
// `read` is the unit the coordinates were taken in.
std::optional<std::string> unitWarning(const BoundingBox& bounds, LengthUnit read);

}  // namespace spira
