#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/mesh_report.h"

namespace spira {

// The 2.5D reference the thesis compares CTPP with (000_dbb97c2716e10cc3.txt §3.4.1.2, Fig. 3.41): the
// part sliced by horizontal planes every h (plane-facet intersection, Choi & Kwok 2002), each
// layer deposited on the one below. The deposit a point of a layer needs is its distance to the
// previous layer: the shortest distance from the point to that layer's contours (to the lower
// free edge for the first layer). On a vertical wall that is h; where the wall leans it grows
// (h / cos of the lean), and near a non-planar upper edge the planes cannot follow it: the edge
// itself, the last "layer" a built part must reach, lies anywhere from 0 to h above the planes
// below it. A closed part's last layer is its highest vertex.
struct PlanarBaselineSettings {
  double h = 2.0;     // plane spacing, mm
  double hMin = 1.8;  // the window the deposits are judged against, mm
  double hMax = 2.2;
  double tolerance = 0.01;  // mm: a deposit is outside the window beyond [hMin - tol, hMax + tol]
};

struct PlanarPoint {
  Vec3 position = Vec3::Zero();
  double height = 0.0;  // mm: distance to the previous layer
  int layer = 0;        // 1 = the first plane above the base; the upper edge gets the last index
};

struct PlanarBaseline {
  std::vector<PlanarPoint> points;  // every contour point of every layer, layer by layer
  int layers = 0;                   // planes cut, plus the upper edge or top point
  double heightMin = 0.0, heightMax = 0.0, heightMean = 0.0;
  size_t outside = 0;  // points outside the window
  bool feasible() const { return outside == 0 && !points.empty(); }
};

// Slices `mesh` from the top of its lower free edge (report.boundaryLoops[lowerLoop]) upwards; the
// other free edges are upper edges. Throws InputError for a non-positive h, a loop index out of
// range or a part shorter than one layer; honours cancellation.
PlanarBaseline planarBaseline(const TriangleMesh& mesh, const MeshReport& report, int lowerLoop,
                              const PlanarBaselineSettings& settings, Progress& progress);

}  // namespace spira
