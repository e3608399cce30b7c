#pragma once

#include <string>

#include "spira/plugin/decomposer.h"
#include "spira/plugin/parameter.h"

namespace spira {

// The discretisation parameters every decomposer shares, declared once: the same keys, ranges and
// defaults, so one CLI flag (--points-per-rev, --level-spacing) and one project value serve every
// strategy. `how` completes the tooltip with what the strategy does with the value.
ParamDef pointsPerRevolutionParam(const std::string& how);
ParamDef levelSpacingParam(const std::string& how);

// The checks every decomposer makes before planning: an open part with two free edges or a closed
// one with one, a lower edge, and a field of the mesh's size when one is given. Returns false with
// the reason in *why otherwise.
bool hasPlannableEdges(const DecomposeInput& input, std::string* why);

}  // namespace spira
