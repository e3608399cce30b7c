#pragma once

#include "spira/mesh/mesh_report.h"
#include "spira/mesh/substrate_surface.h"
#include "spira/planning/part_topology.h"

namespace spira {

// A part built on a substrate mesh (a pipe, a curved plate, a previous part): its base edge is the
// boundary loop that lies on the substrate (the nearest to it on average, unless `lowerOverride` names
// one), and every vertex of it must lie within `tolerance` of the substrate's surface, or the first
// revolution would start in mid-air or inside it. Sets topology.lower (and upper) and
// lowerGapToSubstrate (the largest distance); throws InputError naming the loop, the distance and where
// it is largest otherwise.
void standOnSubstrateMesh(PartTopology& topology, const MeshReport& report, const TriangleMesh& mesh,
                          const SubstrateSurface& substrate, int lowerOverride, double tolerance);

}  // namespace spira
