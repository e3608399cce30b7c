#pragma once

#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Helpers on per-vertex scalar fields (values[v] for every vertex v of the mesh).

// The vertex with the largest finite value (the lowest id among equals); -1 if there is none.
// For a distance from the base it is the closure point of a closed part (thesis 000_dbb97c2716e10cc3.txt
// §3.3.2.2, Eq. 3.10).
int argmaxVertex(const std::vector<double>& values);

// The field at a point of `face` given by barycentric weights (w0, w1, w2) of its vertices,
// linear inside the face. Throws InputError if the face does not exist.
double interpolateField(const TriangleMesh& mesh, const std::vector<double>& values, int face,
                        const Vec3& barycentric);

// Gradient of the piecewise-linear field on one face (thesis Appendix A.4), a vector in the face
// plane, in value units per mm; zero on a face of zero area.
Vec3 faceGradient(const TriangleMesh& mesh, const std::vector<double>& values, int face);
std::vector<Vec3> faceGradients(const TriangleMesh& mesh, const std::vector<double>& values);

}  // namespace spira
