#pragma once

#include <utility>
#include <vector>

#include "spira/collision/triangle_bvh.h"

namespace spira {

// Mesh against mesh, each placed by its own transform (T_world_a maps a's coordinates into a common
// world frame; so does T_world_b). The kinematics call these per path point with robot link meshes
// placed by forward kinematics against the part, table or positioner. Surfaces are compared: a mesh
// wholly inside a closed other mesh is not reported (a continuous motion crosses the surface first).
// margin 0 asks whether the surfaces cross or touch (exact triangle-triangle tests); margin > 0
// whether they come within `margin` mm (GJK on triangle pairs).

bool meshesIntersect(const TriangleBvh& a, const Transform& T_world_a, const TriangleBvh& b,
                     const Transform& T_world_b, double margin = 0.0);

// Same, for a mesh without a hierarchy (built once per call would cost more than it saves for a
// small link): every triangle of `meshA`, carried into b's frame by T_b_a, is queried against b.
bool meshIntersects(const TriangleMesh& meshA, const Transform& T_b_a, const TriangleBvh& b,
                    double margin = 0.0);

// Every pair (face of a, face of b) within `margin`, sorted; stops after `maxPairs` pairs.
std::vector<std::pair<size_t, size_t>> intersectingFaces(const TriangleBvh& a, const Transform& T_world_a,
                                                         const TriangleBvh& b, const Transform& T_world_b,
                                                         double margin = 0.0, size_t maxPairs = 100000);

}  // namespace spira
