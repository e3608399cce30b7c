#pragma once

#include <functional>
#include <memory>

#include "spira/contour/constant_distance.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// The surface of a meshed tube seen from its guide curve: S(t, v) is where the ray from g(t), across
// the guide at angle v on its parallel-transported frame (guided_tube.h), first meets the mesh. So
// the constant-distance layers run on the part's own facets, not on an analytic model of it.
// The mesh is copied into the surface. Throws InputError for an empty mesh or a guide whose rays miss
// the mesh at the base (a guide that leaves the part). Where a later ray misses, S is NaN: no distance
// compares as delta there, so a layer that would need it ends the layers as incomplete.
TubeSurface meshedTube(const TriangleMesh& mesh, std::function<Vec3(double)> guide, double t0, double t1,
                       double reach, int samples = 4096);

}  // namespace spira
