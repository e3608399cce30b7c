#pragma once

#include <string>
#include <vector>

namespace spira::test::real {

// Whether spira-cli's output tells the user what to do: a parenthesised hint after an error
// ("spira-cli: what (do this)") or a "hint:", "advice:" or "try" line, opening with an imperative verb
// (set, use, choose, export, ...). A bare "INFEASIBLE" count is not a hint.
bool hasActionableHint(const std::string& output);

// The hints found in `output` (for the failure messages and the report).
std::vector<std::string> actionableHints(const std::string& output);

// Whether `text` contains one of `words` (case-insensitive).
bool mentionsAny(const std::string& text, const std::vector<std::string>& words);

}  // namespace spira::test::real
