#pragma once

#include <cstdint>
#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// One skin of a thin-walled solid, the faces to keep for its mid-surface (1 per face).
//
// `wall` marks the faces whose inward ray crossed the wall to the opposite skin, `hitFace` the
// face each ray met (-1: none). Wall faces joined across edges form patches; a patch's rays land
// on the patch across the wall, so the patches take two sides, like the two skins. The other faces
// (rims, ledges of a stepped wall, faces whose ray grazed an edge) join a side when every patch
// they border is on it: a ledge or a pin-hole stays in its skin, an end annulus (bordering both
// skins) is left out. The larger side is kept: the outer skin of a tube or a cup.
std::vector<std::uint8_t> outerSkin(const TriangleMesh& mesh, const std::vector<std::uint8_t>& wall,
                                    const std::vector<int>& hitFace);

}  // namespace spira
