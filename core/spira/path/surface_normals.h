#pragma once

#include <vector>

#include "spira/path/trajectory.h"

namespace spira {

// Unit surface normals for generatrices that came without them, one per point (the shape of
// `g.lines`). At each point the normal is (next generatrix - previous generatrix) x (direction of
// this generatrix), both neighbours read at the same fraction of their length; the generatrices
// are taken as a closed loop around the part. With generatrices ordered in the travel direction
// this makes b = n x t point up the generatrices. Where the neighbours meet (a closure point) the
// normal of the nearest regular point of the same generatrix is used.
// Throws InputError when a whole generatrix has no usable neighbours (fewer than 3 generatrices,
// or all of them on one line).
std::vector<std::vector<Vec3>> estimateNormals(const Generatrices& g);

}  // namespace spira
