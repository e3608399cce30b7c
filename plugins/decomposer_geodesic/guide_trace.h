#pragma once

#include <vector>

#include "geodesic_mesh.h"

namespace spira::geodesic {

// Where a guide trace ends: on the upper edge (open parts) or at the closure point (closed ones).
struct TraceGoal {
  const std::vector<char>* upperVertex = nullptr;  // open parts: 1 at the vertices of the upper edge
  int closureFace = -1;                            // closed parts: the face holding the closure point
  int closureVertex = -1;                          // closed parts: the vertex the guide field starts from
};

struct GuideTrace {
  // The faces the trace crossed (a sleeve from the start to the goal), with the faces around the
  // vertices it passed through.
  std::vector<int> faces;
  std::vector<int> endVertices;  // open parts: the upper-edge vertices where the trace arrived
  bool reached = false;
};

// Follows -grad phi, phi being an approximate distance to the goal per vertex (the heat method),
// from `start` face by face: the guide around which the exact geodesic is searched. Where the
// descent runs into an edge that both neighbouring faces slope towards (a valley of the P1
// field) or into a free edge, it follows the edge down to its lower vertex, and from a vertex it
// takes the steepest face or edge downhill. `reached` is false when it gets stuck before the goal.
GuideTrace traceGuide(const GeodesicMesh& mesh, const std::vector<double>& phi, const SurfacePoint& start,
                      const TraceGoal& goal);

}  // namespace spira::geodesic
