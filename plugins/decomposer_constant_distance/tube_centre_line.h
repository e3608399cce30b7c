#pragma once

#include <string>
#include <vector>

#include "spira/mesh/boundary_loops.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/path/trajectory.h"

namespace spira {

// A tube's guide curve (004_bd0df31205c0c3c0.txt §2.3.2) read off the part: the centroids of the
// harmonic field's level loops, from the lower edge's centroid to the upper edge's. On a tube the
// field's levels are its cross-sections (exactly so on a torus segment, where the field is linear in
// the bend angle), so their centroids trace its centre line: the part's level-set skeleton.
// Throws InputError where a level parts into several loops (a branch, a hole through the wall): the
// part is not one tube.
Polyline centreLineFromField(const TriangleMesh& mesh, const std::vector<double>& field,
                             const BoundaryLoop& lower, const BoundaryLoop& upper, int levels = 48);

// A guide curve given by the user: one point per line, "x,y,z" in mm (commas, semicolons, spaces or
// tabs between), an optional header line, '#' comments. Throws IoError when the file is missing or is not
// a regular file, and InputError naming the line for anything else than three finite numbers, or fewer
// than 2 distinct points.
Polyline readGuideCsv(const std::string& path);

// The mean distance of a boundary loop's vertices from its centroid (loopCentroid).
double loopRadius(const TriangleMesh& mesh, const BoundaryLoop& loop);

}  // namespace spira
