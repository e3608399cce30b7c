#pragma once

#include <filesystem>

#include "spira/planning/strategy_compare.h"

namespace spira {

// Reads what `spira-cli compare` wrote: `file` is compare.json or compare.csv (or their folder);
// the other file of the pair is read from the same folder when it is there. compare.json gives
// the window and each strategy's summary; compare.csv each strategy's points and heights (a
// strategy named only in the CSV is listed as ran, with statistics made from its points).
// Throws IoError when neither can be read and InputError when one is malformed.
Comparison readComparison(const std::filesystem::path& file);

}  // namespace spira
