#pragma once

#include "spira/path/trajectory.h"

namespace spira {

// Where the spiral's seam goes. Each revolution starts on generatrix 0 and the start-up and
// closing ramps climb most of a layer at the seam. Where generatrix 0 leans along the travel, each
// revolution's first point lands beside the previous one's, over the foot (leaning backwards) or
// the top (forwards) of the seam below: the bead there is a seam's climb thicker or thinner than
// planned (on a Y tube's arm leaning 13 degrees, 3.2 mm beads on a 1.8 .. 2.2 mm window). The
// seam is therefore put on the generatrix that leans least along the travel where the ramps lie:
// over its first `reach` mm and, on an open part, its last.
//
// `g` has its normals (as prepareGeneratrices leaves them). Returns the generatrix to start from:
// 0 unless another leans less by more than `margin` (the sine of the lean), so a part whose
// generatrices do not lean along the travel keeps its seam.
int leastLeaningSeam(const Generatrices& g, double reach, double margin = 0.02);

// The same generatrices, numbered from `first` on: line k of the result is line (first + k) % n.
Generatrices startingAt(const Generatrices& g, int first);

}  // namespace spira
