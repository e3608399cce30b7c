#pragma once

#include <vector>

#include "spira/mesh/boundary_loops.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// A watertight copy of an open part, for algorithms that need a closed surface (the mean
// curvature flow skeleton contracts a closed surface onto its curve skeleton; an open one has
// no inside to collapse into). Each boundary loop is capped with a fan of triangles from a new
// vertex at the loop's centroid, oriented like the faces around it, so the copy stays
// consistently oriented. The cap is temporary scaffolding: on a flat or gently curved rim it
// lies where a lid would, and the skeleton ends near it as it would on the lidded part.
struct CappedSurface {
  TriangleMesh mesh;     // the part's vertices and faces first, then one centre vertex and fan per cap
  size_t capsAdded = 0;  // boundary loops capped
};

// `loops` are the part's boundary loops (MeshReport::boundaryLoops). Loops that are not closed
// chains, or have fewer than 3 vertices, are left open.
CappedSurface capBoundaryLoops(const TriangleMesh& mesh, const std::vector<BoundaryLoop>& loops);

}  // namespace spira
