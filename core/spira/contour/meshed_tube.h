#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "spira/contour/constant_distance.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// The surface of a meshed tube seen from its guide curve: S(t, v) is where the ray from g(t), across
// the guide at angle v on its parallel-transported frame (guided_tube.h), first meets the mesh. So
// the constant-distance layers run on the part's own facets, not on an analytic model of it.
// The mesh is copied into the surface. Throws InputError for an empty mesh or a guide none of whose
// rays meets it (a guide outside the part). Where a ray misses, S is NaN: no distance compares as
// delta there, so a layer that would need it ends the layers as incomplete.
TubeSurface meshedTube(const TriangleMesh& mesh, std::function<Vec3(double)> guide, double t0, double t1,
                       double reach, int samples = 4096);

// The tube's base edge as a first layer: per point i (v = 2 pi i / points), the lowest t in
// [tFrom, tTo] at which the ray meets the mesh, to `tolerance` in t. A guide from a skeleton or a CSV
// is rarely square to the base; starting it a little below the base and taking the layer from the mesh
// keeps the first layer on the part's own edge. Throws InputError where no ray in the range meets it.
std::vector<double> baseLayer(const TubeSurface& tube, int points, double tFrom, double tTo,
                              double tolerance = 1e-6);

// The tube's upper edge the same way: per point, the highest t in [tFrom, tTo] at which the ray meets
// the mesh. Throws InputError where no ray in the range meets it.
std::vector<double> topLayer(const TubeSurface& tube, int points, double tFrom, double tTo,
                             double tolerance = 1e-6);

}  // namespace spira
