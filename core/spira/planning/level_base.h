#pragma once

#include "spira/mesh/boundary_loops.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// A part whose base edge is not level (requireLevelBase), cut by the horizontal plane through the
// edge's highest point: everything below it goes, so the new base edge lies in that plane.
struct LevelledBase {
  TriangleMesh mesh;
  double cutZ = 0.0;     // the plane, mm
  double removed = 0.0;  // height taken off the base, mm (the old edge's z range)
};

// Throws InputError when the cut leaves more than one piece (the wall dips below the plane away
// from its base) or nothing.
LevelledBase levelBase(const TriangleMesh& mesh, const BoundaryLoop& lower);

}  // namespace spira
