#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// The steady conduction field of an open part (thesis 000_dbb97c2716e10cc3.txt §3.3.2.4, Eq. 3.13): the
// discrete harmonic function (P1 finite elements, stiffness = -L_C) equal to 0 on the `lower` vertices and 1
// on the `upper` vertices. Its iso-lines follow a non-planar upper edge. Solved directly (supernodal Cholesky
// after a nested-dissection ordering).
//
// Vertices in a part of the mesh that touches neither set get NaN.
// Throws InputError if a set is empty, names a missing vertex, or the two sets share a vertex.
std::vector<double> harmonicField(const TriangleMesh& mesh, const std::vector<int>& lower,
                                  const std::vector<int>& upper, Progress& progress);
std::vector<double> harmonicField(const TriangleMesh& mesh, const std::vector<int>& lower,
                                  const std::vector<int>& upper);

}  // namespace spira
