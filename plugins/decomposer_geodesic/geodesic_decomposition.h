#pragma once

#include <optional>
#include <string>
#include <vector>

#include "length_spread.h"
#include "spira/base/progress.h"
#include "spira/mesh/boundary_loops.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/path/trajectory.h"

namespace spira::geodesic {

struct GeodesicOptions {
  size_t pointsPerRevolution = 360;  // n_pts: base points, one geodesic generatrix each
  double pointSpacing = 0.0;         // mm between generatrix points; <= 0: the mean edge length
  double coverageTolerance = 0.2;    // eps_0 of Eq. 3.9, mm
  int fillRounds = 6;                // at most this many rounds of fill-in generatrices
  size_t maxLinesFactor = 16;        // and at most this many times n_pts generatrices in all
  // What the spiral will lay; unknown (zero) turns the checks that need it off.
  LayerWindow window;
  double beadWidth = 0.0;  // mm
};

// Where the time went and how the exact searches went, for reports and the benchmark.
struct GeodesicStats {
  double guideSeconds = 0.0;     // set-up: connectivity, the approximate distance to the target
  double pathSeconds = 0.0;      // the exact geodesics
  double coverageSeconds = 0.0;  // Eq. 3.8-3.9 and the fill-ins
  size_t geodesics = 0;
  size_t fillIns = 0;
  int fillRounds = 0;
  double coverageError = 0.0;  // largest eps left between neighbours, mm
  size_t untraced = 0;         // generatrices whose guide got stuck
  size_t widened = 0;          // searches that needed more than one ring of faces
  size_t wholeMesh = 0;        // searches that needed the whole mesh
  double meanBandFaces = 0.0;  // faces of the band each exact search ran on
};

struct GeodesicDecomposition {
  // Base first; lines[i] starts at the i-th point around the base in the lower edge's direction
  // (counter-clockwise seen from above on an outward-facing part standing on +Z), all with the
  // same number of points at equal arc-length fractions, with unit surface normals. Closed parts:
  // every line ends exactly at the closure point.
  Generatrices generatrices;
  std::vector<bool> fillIn;          // per line: inserted by the coverage check (not a geodesic)
  std::vector<double> exactLengths;  // per line: the exact geodesic distance (fill-ins: polyline length)
  std::vector<std::string> warnings;
  GeodesicStats stats;
};

// The thesis's geodesic-distance decomposition (000_dbb97c2716e10cc3.txt §3.3.2.2): n_pts base points at
// constant angle around the vertical axis through the base centroid, from each the exact shortest path to the
// nearest point of the upper edge (Eq. 3.7; open parts, `upper` given) or to the closure point (closed
// parts), then the coverage check between neighbours with fill-in generatrices (Eq. 3.8-3.9).
// Closed parts take `closurePoint` (from a closure finder) or else the farthest vertex from the
// base along `baseDistance` (the geodesic distance from the lower edge, computed here if null).
//
// Throws InputError when the base does not go around its centroid, or when the target cannot be
// reached from a base point on the surface; and, when the window is known, when the generatrices
// cannot make one spiral in it: before the exact searches when bounds on their lengths already
// break thesis Eq. 3.6, after them when the exact lengths do, and during them as soon as two
// neighbouring generatrices meet (see MergedNeighbours; fill-ins cannot part them). Cancelled when
// `progress` is cancelled.
GeodesicDecomposition decomposeByGeodesics(const TriangleMesh& mesh, const BoundaryLoop& lower,
                                           const BoundaryLoop* upper, const std::optional<Vec3>& closurePoint,
                                           const std::vector<double>* baseDistance,
                                           const GeodesicOptions& options, Progress& progress);

}  // namespace spira::geodesic
