#pragma once

#include <functional>
#include <vector>

#include "strip_unfolding.h"
#include "submesh_geodesics.h"

namespace spira::geodesic {

// Re-places the edge crossings of an exact path so that its polyline is as short as the exact
// length says. Where a geodesic runs along a mesh edge (a cylinder's generatrix through the
// vertices of its base), CGAL unfolds the crossings of the edges fanning out from that edge with
// an ill-conditioned intersection, and a crossing can land at the far end of its edge: the
// polyline then zig-zags to the neighbouring edge and back though the distance is right. Each
// crossing may only slide along its own edge, where the shortest polyline through it is the
// straight line of the unfolded strip (strip_unfolding.h), which is tried first. Coordinate
// descent on the convex length (each crossing at the minimum of |prev - x| + |x - next| on its
// edge) then polishes it; alone it crawls (a whole generatrix on the wrong edge ends moves a
// little per sweep). Runs only while the polyline is longer than `exactLength` by more than 1e-9
// relative, at most `maxSweeps` sweeps.
// The unfolding may add crossings (see straightRun). Returns the polyline length after.
double straightenPath(ExactPath& path, double exactLength, const StripMesh& mesh, int maxSweeps = 400);

}  // namespace spira::geodesic
