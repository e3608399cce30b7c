#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/contour/contour_loop.h"
#include "spira/mesh/boundary_loops.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/path/trajectory.h"

namespace spira {

struct IsoDecompositionOptions {
  size_t pointsPerContour = 360;  // n_pts: points per contour = number of generatrices
  // Spacing of the iso-levels along the surface, mm; <= 0 picks the mesh's mean edge length. The
  // field's levels are spaced evenly in value, so that the mean spacing on the surface is this
  // (the field's mean gradient converts: 1 for a distance field, 1/height for a harmonic one).
  double levelSpacing = 0.0;
  size_t maxLevels = 20000;  // more levels are clamped (with a warning)
};

struct IsoDecomposition {
  // lines[m] is generatrix m, base first; lines[0] is the principal generatrix, and generatrix m
  // starts at point (k_0 + m) mod n of the base contour, so the lines follow the base loop in its
  // direction (counter-clockwise seen from above on a part standing on +Z). normals has the same
  // shape. Closed parts: every line ends at the closure point.
  Generatrices generatrices;
  std::vector<std::string> warnings;
  std::vector<ResampledLoop>
      contours;  // resampled contours used, base first (the upper edge last on open parts)
  std::vector<size_t> principalIndex;  // k_c: the principal generatrix's point on each contour (the
                                       // contours are linked point by point, so all equal k_0)
  double levelSpacing = 0.0;           // mm, the spacing actually used
};

// Iso-value decomposition (thesis 000_dbb97c2716e10cc3.txt §3.3.2.4): the iso-contours of `field` from the
// lower edge up to the upper edge (open parts, `upper` given; the field should be the harmonic field,
// constant on both edges) or to just below the field's maximum (closed parts; the field should be the
// geodesic distance from the lower edge). The base is resampled to n points evenly spaced; every contour
// above is resampled to n points parameterised by the one below it (least-shear correspondence,
// loop_following.h), so point k of each contour lies where point k of the one below lands along
// the field's gradient, and the generatrices run orthogonal to the contours. The principal
// generatrix is the shortest of these chains (generatrix_chain.h).
// `closurePoint` (closed parts): from a closure finder; otherwise the vertex of maximal field.
//
// Throws InputError when the field does not fit the part (wrong size, decreasing away from the
// lower edge, an iso-contour that runs into a free edge) and when the part is multi-branch: "the
// part splits into N branches at field value c (about z = ... mm)".
IsoDecomposition decomposeByIsoValues(const TriangleMesh& mesh, const std::vector<double>& field,
                                      const BoundaryLoop& lower, const BoundaryLoop* upper,
                                      const std::optional<Vec3>& closurePoint,
                                      const IsoDecompositionOptions& options, Progress& progress);

// Area-weighted mean of |grad field| over the faces (the P1 gradient), in field units per mm.
double meanFieldGradient(const TriangleMesh& mesh, const std::vector<double>& field);

}  // namespace spira
