#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/prep/prep_params.h"
#include "spira/prep/sample_set.h"

namespace spira {

// Greedy point skipping (002_4d923f9355c20a15.txt §I.3): from the last kept sample i, reach as far
// as the tolerances allow - every skipped sample within `chordTolerance` of the straight segment and
// within its channel and orientation tolerances of the interpolated values (SampleSet::fits) - but
// no further than `maxSpacing` of path and never past a protected sample.
//
// The source tests the candidates one by one and stops at the first failure. Here the reach grows by
// doubling and a failure is bisected, so a segment of m samples costs O(m log m) instead of O(m^2)
// (a long straight line would otherwise be quadratic). The acceptance test is the same; as the test
// is not monotonic in the reach, the search may land beyond the source's first failure, never on a
// segment that fails.
//
// `minSpacing` then wins over the tolerances: a segment shorter than it is stretched to it (counted in
// `spacingOverrides`; the report measures what that costs), and the last point before a protected one
// is moved back when it would land closer than `minSpacing` to it and a fitting alternative exists.
struct Selection {
  std::vector<size_t> kept;     // increasing sample indices, first and last included
  size_t spacingOverrides = 0;  // segments stretched to minSpacing beyond the tolerances
};

Selection selectSamples(const SampleSet& samples, const PrepParams& params, Progress& progress);

}  // namespace spira
