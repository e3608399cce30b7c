#pragma once

#include "spira/path/trajectory.h"

namespace spira {

// `count` generatrices spread evenly (by index) around the loop of `g`. Generatrix j lies at
// tau = j n / count between input generatrices a = floor(tau) and a + 1 (the last one wraps to the
// first); where tau is not whole, its points blend the two neighbours at equal fractions of their
// lengths, positions and normals with the weight tau - a. Blended points lie on the chords between
// neighbours, not on the surface: the chordal error of the input discretisation. `g.normals` must
// be filled. Throws InputError for count < 3.
Generatrices resampleGeneratrices(const Generatrices& g, int count);

}  // namespace spira
