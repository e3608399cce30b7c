#pragma once

#include <vector>

#include "spira/path/trajectory.h"

namespace spira {

// The surface normals of a layered path from its points alone, for a path made elsewhere (Chalvin
// §2.4.3, Eq. 2.36, in 004_bd0df31205c0c3c0.txt). At point v of a closed layer the lower facet is
// (M[v+1], M[v-1], the nearest point of the layer below) and the upper facet (M[v+1], M[v-1], the
// nearest point of the layer above); the normal is the mean of the two facets' normals, the first
// layer's from its upper facet only and the last layer's from its lower facet only. The normals are
// oriented so that b = n x t, with t from M[v-1] to M[v+1], points from the layer below to the one
// above. Layers in build order, each a closed loop of 3 or more points; needs 2 or more layers.
std::vector<std::vector<Vec3>> facetNormals(const std::vector<Polyline>& layers);

// The nearest point of the closed loop `loop` to p, over all its segments (the closing one included).
Vec3 nearestOnLoop(const Vec3& p, const Polyline& loop);

}  // namespace spira
