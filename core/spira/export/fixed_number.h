#pragma once

#include <string>

#include "spira/base/number_text.h"  // roundedTo

namespace spira {

// Appends `x` rounded to `decimals` places in plain fixed notation ("12.500", "-0.004"), the
// way robot program files write numbers. A value that rounds to zero prints without a sign, so
// "-0.000" never appears. `width` > 0 pads with spaces on the left to that many characters.
void appendFixed(std::string& out, double x, int decimals, int width = 0);

}  // namespace spira
