#pragma once

#include <vector>

#include "spira/path/trajectory.h"

namespace spira {

// The thesis's "Frenet" frame at every point (000_dbb97c2716e10cc3.txt §3.3.4): n is the surface normal
// already stored in the point, t the unit direction to the next point and b = n x t the build direction. The
// chord to the next point is projected into the tangent plane before normalising, so (t, b, n) is an
// orthonormal, right-handed frame the torch can use directly. The last point, and points that
// coincide with the next one, take the tangent of the nearest point before them (after them at the
// very start).
// The seam is the exception: the last point of a revolution takes the chord that arrives at it,
// not the one that climbs to the next revolution. The seam chord climbs the whole revolution's rise
// (up to h_min where the spiral levels out onto a flat edge) in one segment; taking its direction
// would tilt b, and the torch, by up to 45 degrees for that one point and report a deposit thinner
// than the one laid (the steps below and above the seam both lie in the window). The seam rise is
// reported separately (SpiralReport::seamRiseMax).
void computeFrames(Trajectory& path);

// steps[q] is the generatrix step vector of point q: from the point of the same generatrix on the
// previous revolution (the base point on the first revolution) to point q. When b points down the
// generatrices overall (sum of b . step < 0: generatrices ordered against the normals' sense), n
// and b are reversed everywhere so the build direction points away from the base. Returns whether
// it did.
bool orientBuildDirection(Trajectory& path, const std::vector<Vec3>& steps);

// True deposit heights, 000_dbb97c2716e10cc3.txt §3.3.4 (unnumbered, docs/method.md M18) with d_i
// in place of the misprinted d_1: h = d cos(theta),
// theta the angle between steps[q] and b, with d the length of the chord steps[q], i.e.
// h = steps[q] . b. The thesis's d is the arc stepped along the generatrix; on its straight
// generatrices the two agree, but across a bend the arc is longer than what lies between the two
// beads (a 1.8 mm step across a tube wall's 19 degree bend: arc 1.828 mm, chord 1.799 mm), and
// the chord is what the deposit check measures (docs/deposit-check.md).
// The first `firstRing` points rest on the level plane their generatrices start on (the substrate,
// or a trunk's level top): their height is the distance from it along b, (steps[q] . z) / b_z, as
// the deposit check measures the substrate, where b_z >= 0.1; on a wall that leans and curves at
// its base the chord's projection on b differs from it by the chord's turn (0.7 % on a dome's rim).
void computeDepositHeights(Trajectory& path, const std::vector<Vec3>& steps, size_t firstRing = 0);

}  // namespace spira
