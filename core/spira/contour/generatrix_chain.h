#pragma once

#include <optional>
#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// The principal generatrix of thesis 000_dbb97c2716e10cc3.txt §3.3.2.4, steps 1-4. Every contour has the same
// number n of points, in the same turning sense. From point k of contour c a greedy chain steps to the point
// of contour c + 1 nearest to it, up to the last contour (and then to the closure point, when
// there is one). The start point on the first contour whose chain is shortest defines the
// principal generatrix; generatrix m then uses point (k_c + m) mod n of contour c, where k_c is
// the principal's index on contour c, so that no two generatrices share a contour point.
struct PrincipalGeneratrix {
  std::vector<size_t> index;  // k_c for every contour; index[0] is the start on the first contour
  double length = 0.0;        // of the principal's chain, mm (closure point included)
};

// `contours[c]` holds contour c's points in order. Throws InternalError when the contours do not
// all have the same non-zero number of points.
PrincipalGeneratrix findPrincipalGeneratrix(const std::vector<std::vector<Vec3>>& contours,
                                            const std::optional<Vec3>& closurePoint,
                                            Progress* progress = nullptr);

// The same rule on contours already linked point by point, where the point of contour c + 1 that
// follows point k of contour c is point k itself (resampleLoopFollowing: the least-shear partner
// takes the place of the nearest point, which, with uneven spacing, may be a neighbour and would
// shift every generatrix by one point there). The principal generatrix is the shortest chain
// k, k, ..., k (closure point included), so k_c = k_0 on every contour; ties go to the lowest k.
// Throws InternalError as findPrincipalGeneratrix does.
PrincipalGeneratrix shortestLinkedGeneratrix(const std::vector<std::vector<Vec3>>& contours,
                                             const std::optional<Vec3>& closurePoint);

}  // namespace spira
