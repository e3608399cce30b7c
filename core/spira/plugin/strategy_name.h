#pragma once

#include <string>

namespace spira {

// A decomposition strategy has one name wherever Spira writes it (report.json, compare.json,
// advice, messages): its decomposer's id without the "decomposer." prefix, e.g. "isovalue". Both
// forms are accepted wherever a strategy is read.
std::string strategyName(const std::string& strategyOrId);
// The decomposer plugin id of a strategy given either way: "isovalue" -> "decomposer.isovalue".
std::string decomposerIdOf(const std::string& strategyOrId);

}  // namespace spira
