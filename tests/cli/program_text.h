#pragma once

#include <cstddef>
#include <set>
#include <string>

namespace spira::test {

// The S (status) values of the "DECL E6POS XP<n>={... S <s>,T ...}" declarations in a KRL .dat
// text, as written (digits only).
std::set<std::string> e6posStatusValues(const std::string& dat);

// The number after "LINE_COUNT = " (spaces optional) and before ';' in a FANUC .ls text; false when
// there is none.
bool tpLineCount(const std::string& ls, size_t& count);

// Whether `line` is a numbered TP instruction: optional leading whitespace, digits, then ':'.
bool isNumberedTpLine(const std::string& line);

}  // namespace spira::test
