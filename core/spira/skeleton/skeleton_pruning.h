#pragma once

#include "spira/mesh/triangle_mesh.h"
#include "spira/skeleton/curve_skeleton.h"

namespace spira {

// Distance from p to the nearest point of the surface (every face; the few callers ask for a
// handful of points).
double distanceToSurface(const TriangleMesh& mesh, const Vec3& p);

// Removes spurs: terminal branches (from an end point to a branch point) shorter than the part's
// radius at their branch point, i.e. its distance to the surface. Such a branch ends inside the
// largest ball the junction's cross-section holds, so it is not a limb of the part but a
// wrinkle of the contraction (typically where a flat cap meets the wall). The shortest spur goes
// first and the graph is re-read after each removal, so of two spurs forking from one point the
// longer one becomes the continuation of the chain. Nodes left without edges are dropped.
// Returns how many spurs were removed.
size_t pruneSpurs(SkeletonGraph& graph, const TriangleMesh& mesh);

}  // namespace spira
