#pragma once

#include <vector>

#include "spira/mesh/boundary_loops.h"

namespace spira {

// A part with more free edges than a base, a top and one per branch, whose walls still do not part
// into branches Spira can lay. When free edges are shorter than one bead ring (`minPerimeter`,
// pi x bead width at least) the branches they end are too narrow for the bead, and the message
// says so with the numbers; otherwise a free edge is a hole in a wall. Loops are numbered from 1,
// as `spira-cli info` lists them. Always throws InputError.
[[noreturn]] void refuseUnbranchedPart(const std::vector<BoundaryLoop>& loops, double minPerimeter,
                                       double beadWidth);

}  // namespace spira
