#pragma once

#include <optional>
#include <string>

#include "spira/mesh/mesh_report.h"

namespace spira {

// Which free edge stands on the substrate and which is the top, for planning.
struct PartTopology {
  PartClass partClass = PartClass::Unsupported;
  int lowerIndex = -1;  // index into MeshReport::boundaryLoops
  int upperIndex = -1;  // open parts only
  BoundaryLoop lower;
  std::optional<BoundaryLoop> upper;
  double lowerGapToSubstrate = 0.0;  // mm: the lower loop's mean distance from the substrate plane
  size_t freeEdgeCount = 0;          // boundary loops of the part
  // More than two free edges (allowed only with `allowBranches`): a multi-branch part, planned as
  // mono-branch sub-parts. partClass is then Unsupported and `upper` empty.
  bool branched = false;
};

// Finds the lower boundary (the loop touching the substrate plane z = substrateZ: the one whose
// mean height is closest to it) and, for open parts, the upper one. `lowerOverride` >= 0 picks the
// lower loop by index instead (the user's choice). Throws InputError, saying what is wrong and what
// to do, for meshes that cannot be planned: defects (non-manifold, inconsistent orientation,
// non-finite), several components, or no boundary loop; and for more than two boundary loops
// unless `allowBranches` (the planner splits such parts into branches, see branch_split.h).
PartTopology findPartTopology(const MeshReport& report, const TriangleMesh& mesh, double substrateZ,
                              int lowerOverride = -1, bool allowBranches = false);

}  // namespace spira
