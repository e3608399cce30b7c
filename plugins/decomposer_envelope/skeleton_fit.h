#pragma once

#include "spira/path/trajectory.h"

namespace spira {

// A skeleton chain as a smooth function of height. The mean curvature flow leaves its nodes
// jittering sideways by a few tenths of a millimetre (by an amount that depends on the order of
// its edge collapses); projected towards such a chain, the generatrices wobble.
// A local linear fit in z keeps the chain's course and drops the jitter: it is exact on a straight
// chain and does not pull the ends in as an average would.
struct HeightFit {
  Polyline points;  // evenly spaced in z over the chain's height, z rising
  // The least-squares straight line x, y = origin + z * slope through the same nodes.
  Vec3 lineOrigin = Vec3::Zero();  // at z = 0
  Vec3 lineSlope = Vec3::Zero();   // xy change per mm of z (its z is 0)
  Vec3 lineAt(double z) const
  {
    return Vec3(lineOrigin.x() + z * lineSlope.x(), lineOrigin.y() + z * lineSlope.y(), z);
  }
};

// `chain` must rise in z overall (small falls are noise). `halfWidth` is how far in z each local
// fit reaches, mm. Throws InputError when the chain has fewer than two nodes or no rise.
HeightFit fitChainByHeight(const Polyline& chain, double halfWidth);

// Largest horizontal distance between the fitted chain (and its line) and the vertical through
// `centre`, over the chain and at the two heights z0 and z1 the part spans.
double largestOffsetFromVertical(const HeightFit& fit, const Vec3& centre, double z0, double z1);

// Largest horizontal distance of the fitted chain from its own straight line.
double largestOffsetFromLine(const HeightFit& fit);

}  // namespace spira
