#pragma once

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/skeleton/curve_skeleton.h"

namespace spira {

// Moves the skeleton's chain nodes (degree 1 or 2) to the centroid of the part's cross-section
// through them: the loop where the plane through the node, normal to the skeleton there, cuts
// the surface and winds once around the node (the nearest such loop). Why: the mean curvature
// flow leaves its nodes a few percent of the radius off the medial axis (its remeshing is not
// symmetric), and for the tube-like parts Spira builds the section centroid is the axis point the
// skeleton stands for. Where that plane runs out through a free edge the horizontal section is
// tried instead (the skeleton bends towards a sloping rim, the part does not). Nodes with no
// closed section around them, and branch points, stay where they are. Returns how many moved.
size_t centreInCrossSections(SkeletonGraph& graph, const TriangleMesh& mesh, Progress& progress);

}  // namespace spira
