#pragma once

#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// One implicit step of the heat flow on a per-vertex field: (A + t K) out = A in, with K the
// cotan stiffness matrix, A the vertex areas and t = timeScale * h^2 (h the mean edge length).
// It damps the noise of a field at the scale of a few edges (the heat method's distance wobbles
// by a few hundredths of a millimetre from face to face on meshes with slivers, so its level
// lines zig-zag) and leaves its shape at larger scales, and its gradient on flat parts, as they
// were. Values on vertices of zero area are kept.
std::vector<double> smoothField(const TriangleMesh& mesh, const std::vector<double>& field, double timeScale);

}  // namespace spira
