#pragma once

#include <string>
#include <vector>

#include "projection_axis.h"
#include "spira/base/progress.h"
#include "spira/mesh/boundary_loops.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/path/trajectory.h"

namespace spira {

struct EnvelopeOptions {
  size_t generatrixCount = 360;  // n_pts: envelope generatrices = points per revolution
  // Distance between consecutive points along a generatrix, mm; <= 0 picks the mesh's mean edge
  // length. Every generatrix gets the same number of points (the mean length / spacing, rounded
  // up), spread evenly along its own length, as the iso-value decomposer gives them.
  double pointSpacing = 0.0;
  double startAngle = 0.0;  // rad: the angle of generatrix 0 about the axis, from +X, counter-clockwise
};

struct EnvelopeDecomposition {
  // lines[m] runs from the lower edge to the upper edge at angle startAngle + 2 pi m / n about the
  // axis, so the lines follow each other counter-clockwise seen from above (the iso-value
  // decomposer's order). Every point lies on the surface; normals has the same shape.
  Generatrices generatrices;
  std::vector<std::string> warnings;
  double envelopeRadius = 0.0;  // mm from the axis
  double pointSpacing = 0.0;    // mm, the spacing asked for (the mean spacing achieved)
  size_t raysCast = 0;
};

// Envelope projection (thesis 000_dbb97c2716e10cc3.txt §3.3.2.1), for open parts. The envelope generatrices
// are vertical lines on a cylinder of radius R about the axis (swept along it when the axis is not vertical),
// R being the part's largest distance from the axis plus a margin: the thesis dilates the envelope until it
// wraps the part, and this one wraps it from the start. Each envelope generatrix is cut to the part: it runs
// from the height where the lower free edge crosses its angle to the height where the upper edge does, which
// is the thesis's length adaptation for non-planar edges. Its points P_i are projected along P_i -> S_i, S_i
// being the axis point at the same height (a horizontal ray, so the order of the points is kept), onto the
// nearest surface hit (ray-triangle intersection through a bounding-volume hierarchy).
//
// Overhangs: where the wall folds back, part of the surface is hidden from the envelope and the
// nearest hits jump across it. Every step between consecutive hits longer than three sampling
// steps is bisected in height until it either closes (a steep but continuous wall) or stays open
// over a vanishing height: then that surface has no projection and the function throws
// InputError naming the height and angle, as it does when a ray meets nothing.
// Also throws InputError when a free edge does not go once around the axis.
EnvelopeDecomposition decomposeByEnvelopeProjection(const TriangleMesh& mesh, const BoundaryLoop& lower,
                                                    const BoundaryLoop& upper, const ProjectionAxis& axis,
                                                    const EnvelopeOptions& options, Progress& progress);

}  // namespace spira
