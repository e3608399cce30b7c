#pragma once

#include <string>

namespace spira {

// The strategy and closure finder a plan uses unless told otherwise (the GUI's new document, the
// CLI without --strategy, a plan request).
inline constexpr char kDefaultDecomposerId[] = "decomposer.isovalue";
inline constexpr char kDefaultClosureFinderId[] = "closure.max_min_geodesic";

// A decomposition strategy has one name wherever Spira writes it (report.json, compare.json,
// advice, messages): its decomposer's id without the "decomposer." prefix, e.g. "isovalue". Both
// forms are accepted wherever a strategy is read.
std::string strategyName(const std::string& strategyOrId);
// The decomposer plugin id of a strategy given either way: "isovalue" -> "decomposer.isovalue".
std::string decomposerIdOf(const std::string& strategyOrId);

}  // namespace spira
