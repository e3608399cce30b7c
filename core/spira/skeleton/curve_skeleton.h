#pragma once

#include <array>
#include <vector>

#include "spira/path/trajectory.h"

namespace spira {

// A curve skeleton as a graph: points (mm, part frame) joined by straight edges.
struct SkeletonGraph {
  std::vector<Vec3> nodes;
  std::vector<std::array<int, 2>> edges;  // node indices, each undirected edge once
};

// The graph read as a topology check (000_dbb97c2716e10cc3.txt §3.3.1): its branches, branch points and
// loops.
struct CurveSkeleton {
  SkeletonGraph graph;
  // Maximal chains of edges between nodes of degree other than 2 (end points and branch points),
  // as polylines of node positions. A cycle with no such node is one branch whose last point
  // repeats its first. A branch touching a branch point starts there; a single open chain runs
  // from its lower end to its upper end.
  std::vector<Polyline> branches;
  std::vector<Vec3> branchPoints;  // nodes of degree >= 3
  std::vector<Vec3> endPoints;     // nodes of degree 1
  size_t loops = 0;                // independent cycles: edges - nodes + components
  size_t components = 0;           // connected pieces of the graph (1 for a connected part)
  // One open chain (one branch, no branch point, no loop) whose z never falls by more than the
  // tolerance given to analyseSkeleton on the way up: one skeleton point per height, as the
  // envelope-projection strategy needs (000_dbb97c2716e10cc3.txt §3.3.2.1 step 2).
  bool monotoneInZ = false;

  size_t branchCount() const { return branches.size(); }
  // Mono-branch in the thesis's sense: one spiral can build the part.
  bool monoBranch() const { return components == 1 && branchPoints.empty() && loops == 0; }
};

// Reads the topology of `graph`. Duplicate edges and self-loops are dropped first; nodes that no
// edge uses count as components of their own. `zTolerance` (mm, >= 0) is the largest fall in z
// along a single chain that still counts as monotone (skeleton noise).
CurveSkeleton analyseSkeleton(SkeletonGraph graph, double zTolerance);

}  // namespace spira
