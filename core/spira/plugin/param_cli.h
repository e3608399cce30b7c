#pragma once

#include <string>
#include <vector>

#include "spira/plugin/parameter.h"

namespace spira {

// Command-line flags generated from parameter schemas: key "linear_deflection" becomes the
// flag "--linear-deflection". One definition feeds the GUI, the CLI and the project file.
std::string flagForKey(const std::string& key);

// A schema bound to the ParamSet that flags fill in (a plugin, or a settings section).
struct FlagTarget {
  std::string owner;  // plugin id or section name, shown in help
  const ParamSchema* schema = nullptr;
  ParamSet* values = nullptr;
};

// Consumes every "--flag VALUE" / "--flag=VALUE" (and bare "--flag" / "--no-flag" for bools)
// that names a parameter of one of `targets`; a key shared by several targets sets all of
// them. Returns the arguments it did not consume, in order. Throws InputError for a known
// flag with a bad value or a missing value.
std::vector<std::string> consumeParamFlags(const std::vector<std::string>& args,
                                           const std::vector<FlagTarget>& targets);

// Help text for the flags of `targets`, grouped by owner and category: flag, value type, unit,
// default, range or choices, and the tooltip.
std::string paramFlagsHelp(const std::vector<FlagTarget>& targets);

}  // namespace spira
