#pragma once

#include <vector>

#include "spira/contour/contour_loop.h"

namespace spira {

struct LoopFollowingOptions {
  // Weight of even spacing against shear. The resampling minimises
  //   sum_k (e_k / g)^2 + spacingWeight * sum_k ((s_k+1 - s_k - L / n) / (L / n))^2,
  // e_k the arc offset of point k from the foot of the previous contour's point k, g the mean
  // distance between the contours (so e_k / g is the tangent of the shear angle), L the length of
  // the contour. 0: pure normal projection, the generatrices follow the field's gradient and bunch
  // where it converges; large: even arc-length spacing, as resampleLoop.
  double spacingWeight = 10.0;
  // No two consecutive points closer than this fraction of the even spacing L / n.
  double minSpacing = 0.25;
};

// Parameterises a closed contour by the previous one (least-shear correspondence): its point k
// lies where the previous contour's point k lands when projected onto it (the foot of the
// perpendicular, which on closely spaced contours is the step along the field's gradient), moved
// along the contour just enough to keep the spacing near even (see LoopFollowingOptions). The
// points keep the previous contour's order and turning sense and never cross. Generatrices that
// link point k of every contour then run "straight up" the surface, orthogonal to the contours,
// instead of shearing across it where consecutive contours differ in shape (a tilted or pinched
// base): uniform arc-length resampling of each contour on its own matches points by the fraction
// of the length, not by where they face each other.
//
// `previous` holds the previous contour's n >= 3 points in order. Where the projection cannot be
// ordered around the loop (it winds the wrong number of times), falls back to resampleLoop
// starting at the foot of previous[0]. Throws InputError for an open contour.
ResampledLoop resampleLoopFollowing(const TriangleMesh& mesh, const IsoContour& loop,
                                    const std::vector<Vec3>& previous,
                                    const LoopFollowingOptions& options = LoopFollowingOptions());

}  // namespace spira
