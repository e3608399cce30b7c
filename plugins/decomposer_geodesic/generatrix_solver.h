#pragma once

#include <vector>

#include "corridor.h"
#include "spira/base/progress.h"
#include "spira/mesh/boundary_loops.h"
#include "submesh_geodesics.h"

namespace spira::geodesic {

// What the generatrices run to: the upper edge (open parts) or the closure point (closed ones).
struct GeodesicTarget {
  const BoundaryLoop* upper = nullptr;  // open parts
  std::vector<int> upperIndex;          // open parts: each vertex's index in upper->vertices, or -1
  std::vector<char> upperVertex;        // open parts: 1 at the vertices of the upper edge
  SurfacePoint closure;                 // closed parts
  int closureVertex = -1;               // closed parts: the corner of the closure face nearest to it
  bool open() const { return upper != nullptr; }
};

struct SolvedGeneratrix {
  ExactPath path;    // from the base point to `end`
  SurfacePoint end;  // on the upper edge (Eq. 3.7) or the closure point
  int rings = 0;     // band width used (rings of faces around the guide), -1: the whole mesh
  size_t bandFaces = 0;
  bool traced = false;  // the guide reached the target
};

// One generatrix (thesis 000_dbb97c2716e10cc3.txt §3.3.2.2): from a base point, the exact shortest path to
// the nearest point of the upper edge (Eq. 3.7: argmin over the upper edge of the geodesic distance, refined
// along its edges between vertices) or to the closure point.
//
// The exact search runs on a band of faces around a guide (traceGuide on an approximate distance
// field to the target), and the band is widened (1, 2, 4, ... 32 rings, then the whole mesh)
// until the result does not depend on where the band was cut: the path passes through no vertex
// of the cut, and on open parts the nearest upper-edge vertex has both its neighbours along the
// edge in the band, neither of which can be nearer on the whole mesh. Exact on the band, the path is then a
// shortest path of the mesh between its ends; the guide decides only which of several near-equal targets is
// taken.
class GeneratrixSolver {
 public:
  GeneratrixSolver(const GeodesicMesh& mesh, const std::vector<double>& guide, const GeodesicTarget& target);

  // Throws InputError when the target cannot be reached from `base` on the surface.
  SolvedGeneratrix solve(const SurfacePoint& base, Corridor& band, const Progress& progress) const;

 private:
  bool attempt(const SurfacePoint& base, Corridor& band, SolvedGeneratrix& out) const;
  // Closed parts: whether the closure point is a mesh vertex (closureVertex), and the closure
  // point as a point of a band face (false when the band does not hold it).
  bool closureAtVertex() const;
  bool closureInBand(const Corridor& band, SurfacePoint& end) const;
  bool chooseUpperEnd(const SubmeshGeodesics& geo, const Corridor& band, const SurfacePoint& base,
                      SurfacePoint& end) const;

  const GeodesicMesh& mesh_;
  const std::vector<double>& guide_;
  const GeodesicTarget& target_;
};

}  // namespace spira::geodesic
