#pragma once

#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Adjacent faces whose normals differ by more than this meet at a feature edge (a wall standing on
// a step, the rim of a flange): their normals are not averaged across it.
constexpr double kDefaultCreaseAngleDeg = 45.0;

// Shading normals per face corner, result[3 * f + k] for vertex faces[f][k]: the mean of the normals
// of the faces around the vertex that lie within `creaseAngleDeg` of face f's normal, each weighted
// by the face's angle at the vertex. Angle weights make the normal independent of how a flat region
// was cut into triangles (a CAD export fans a planar annulus from one vertex, which area weights
// let tilt that vertex's normal by tens of degrees), and the crease limit keeps a wall's normal
// off the face it meets at a sharp edge. Interpolated over a face, these normals vary smoothly
// across gentle curvature and keep each side of a feature edge its own. Zero-area faces get their
// corners' normals from the other faces, or zero when the vertex has no other face.
std::vector<Vec3> cornerNormals(const TriangleMesh& mesh, double creaseAngleDeg = kDefaultCreaseAngleDeg);

}  // namespace spira
