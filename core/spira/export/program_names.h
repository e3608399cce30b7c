#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace spira {

// What a controller accepts as a program name (which is also the file name).
struct ProgramNameRules {
  size_t maxLength = 24;
  bool uppercase = false;             // FANUC shows and stores names in capitals
  std::string fallback = "SPIRA";     // used when nothing usable is left
  std::vector<std::string> reserved;  // keywords a name may not equal (compared case-insensitively)
};

// KUKA KRL: a KRL identifier, at most 24 characters of letters, digits and '_', starting with a
// letter; case is kept (KRL ignores it); language keywords are refused.
const ProgramNameRules& krlNameRules();
// FANUC TP: at most 36 characters of capital letters, digits and '_', starting with a letter
// (R-30iA and later; the R-J3 generation allowed 8).
const ProgramNameRules& fanucNameRules();

// A valid name made from `wanted`: characters outside [A-Za-z0-9_] become '_', runs of '_' are
// merged and trimmed, a leading digit gets a "P" in front, the result is cut to the length limit,
// and a reserved word gets "_PRG" appended. Empty input gives the fallback.
std::string sanitizeProgramName(std::string_view wanted, const ProgramNameRules& rules);

// Names for a program split into `partCount` sub-programs: the main program and the parts
// "<base>_001", "<base>_002", ... all valid under `rules`, the base shortened to leave room for
// the suffix. With partCount 0 only the main name is given.
struct ProgramNames {
  std::string main;
  std::vector<std::string> parts;
};
ProgramNames splitProgramNames(std::string_view wanted, size_t partCount, const ProgramNameRules& rules);

}  // namespace spira
