#pragma once

#include <vector>

namespace spira {

// The least profile e >= 0 with e[i] >= magnitude[i] everywhere and |e[i+1] - e[i]| <= maxStep:
// e[i] = max_j (magnitude[j] - maxStep * |i - j|), clipped at 0. Each required tilt is thus ramped
// in before and out after its point at the largest allowed rate, and neighbouring ramps merge.
// Two linear passes (forward, backward).
std::vector<double> rampEnvelope(const std::vector<double>& magnitude, double maxStep);

}  // namespace spira
