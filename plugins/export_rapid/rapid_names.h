#pragma once

#include <string>

#include "spira/export/program_names.h"

namespace spira {

// ABB RAPID identifiers (RAPID reference manual, "Identifiers" and "Reserved words"): at most 32
// characters, letters, digits and '_', starting with a letter, not one of RAPID's reserved words.
// Case is kept; RAPID compares identifiers without case.
const ProgramNameRules& rapidNameRules();

// True when `name` is a RAPID identifier under rapidNameRules().
bool isRapidIdentifier(const std::string& name);

// Why `name` cannot name a data object the program declares (empty when it can): not an identifier,
// a reserved word, a predefined data object of the controller (tool0, wobj0, load0, fine, v100,
// z1...), or one of the names the writer generates (main, pApproach, p123...).
std::string rapidDataNameProblem(const std::string& name);

// The module name the writer uses for `wanted`: sanitizeProgramName under rapidNameRules().
std::string rapidModuleName(const std::string& wanted);

}  // namespace spira
