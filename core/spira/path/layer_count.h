#pragma once

#include <vector>

#include "spira/path/spiral_report.h"
#include "spira/path/spiral_settings.h"

namespace spira {

// Number of modulated revolutions for the lengths L each generatrix has left for that phase
// (see LayerMode). 0 when even the shortest cannot take one layer of h_min.
int countLayers(const std::vector<double>& lengths, double h, double hMin, double hMax, LayerMode mode);

// Eq. 3.6 for these lengths and layer count.
LengthCriterion lengthCriterion(const std::vector<double>& lengths, int nLayers, double hMin, double hMax);

// Eq. 3.6 as the thesis applies it right after the decomposition: on the full generatrix lengths G
// with n_layer = floor(min(G) / h_min). Table 3.3: G in [152, 178] mm at 2 +/- 0.2 mm gives 84 and
// a spread of 0.31 <= 0.4 mm, "valid".
LengthCriterion thesisLengthCriterion(const std::vector<double>& lengths, double hMin, double hMax);

}  // namespace spira
