#pragma once

#include <optional>
#include <string>

#include "spira/base/error.h"
#include "spira/mesh/mesh_report.h"

namespace spira {

// Which free edge stands on the substrate and which is the top, for planning.
struct PartTopology {
  PartClass partClass = PartClass::Unsupported;
  int lowerIndex = -1;  // index into MeshReport::boundaryLoops
  int upperIndex = -1;  // open parts only
  BoundaryLoop lower;
  std::optional<BoundaryLoop> upper;
  // mm from the substrate plane up to the lower loop's lowest point: negative when the part reaches
  // below the substrate, positive when it floats above it.
  double lowerGapToSubstrate = 0.0;
  size_t freeEdgeCount = 0;  // boundary loops of the part
  // More than two free edges (allowed only with `allowBranches`): a multi-branch part, planned as
  // mono-branch sub-parts. partClass is then Unsupported and `upper` empty.
  bool branched = false;
};

// Finds the lower boundary (the part's lowest loop by mean height: the one on the substrate plane
// z = substrateZ or, for a part placed away from it, the one facing it) and, for open parts, the
// upper one. `lowerOverride` >= 0 picks the lower loop by index instead (the user's choice; 'info'
// and the GUI show index + 1). Throws InputError, saying what is wrong and what
// to do, for meshes that cannot be planned: defects (non-manifold, inconsistent orientation,
// non-finite), several components, or no boundary loop; and for more than two boundary loops
// unless `allowBranches` (the planner splits such parts into branches, see branch_split.h).
PartTopology findPartTopology(const MeshReport& report, const TriangleMesh& mesh, double substrateZ,
                              int lowerOverride = -1, bool allowBranches = false);

// Throws InputError when the part's lower loop is more than `tolerance` mm from the substrate plane,
// with the gap and the changes that put it there (drop the part, or move the substrate plane).
void requireOnSubstrate(const PartTopology& topology, double substrateZ, double tolerance);

// A base edge that is not level: its loop, for the cut that levels it (level_base.h).
class BaseNotLevelError : public InputError {
 public:
  BaseNotLevelError(const std::string& what, const std::string& hint, BoundaryLoop lower)
      : InputError(what, hint), lower_(std::move(lower))
  {
  }
  const BoundaryLoop& lower() const { return lower_; }

 private:
  BoundaryLoop lower_;
};

// Throws BaseNotLevelError when the lower loop rises more than `tolerance` mm above the substrate
// plane somewhere along it (an obliquely cut scan, a base edge that follows a curved face): the
// first revolution would hang in mid-air there. The hint names the cut that levels it.
void requireLevelBase(const PartTopology& topology, double substrateZ, double tolerance);

}  // namespace spira
