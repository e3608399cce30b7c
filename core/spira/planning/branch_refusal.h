#pragma once

#include <string>
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

// A sub-part of a split part that still has more free edges than a base and a top: one of its
// branches narrows below one bead ring (`minPerimeter`) between the junction and its free edge,
// so it was not split off. `role` names the sub-part ("sub-part 0 (trunk)"). Always throws
// InputError.
[[noreturn]] void refuseUnsplitBranch(const std::string& role, size_t freeEdges, double minPerimeter);

}  // namespace spira
