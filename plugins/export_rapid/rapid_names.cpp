#include "rapid_names.h"

#include <algorithm>
#include <cctype>

namespace spira {

namespace {

std::string upper(std::string s)
{
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// "v100", "z10", "p42": a letter prefix and digits only.
bool prefixAndDigits(const std::string& name, const std::string& prefix)
{
  if (name.size() <= prefix.size() || upper(name.substr(0, prefix.size())) != upper(prefix)) return false;
  return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(prefix.size()), name.end(),
                     [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

const ProgramNameRules& rapidNameRules()
{
  static const ProgramNameRules rules{
      32, false, "spira", {"ALIAS",     "AND",     "BACKWARD",  "CASE",    "CONNECT",  "CONST",    "DEFAULT",
                           "DIV",       "DO",      "ELSE",      "ELSEIF",  "ENDFOR",   "ENDFUNC",  "ENDIF",
                           "ENDMODULE", "ENDPROC", "ENDRECORD", "ENDTEST", "ENDTRAP",  "ENDWHILE", "ERROR",
                           "EXIT",      "FALSE",   "FOR",       "FROM",    "FUNC",     "GOTO",     "IF",
                           "INOUT",     "LOCAL",   "MOD",       "MODULE",  "NOSTEPIN", "NOT",      "NOVIEW",
                           "OR",        "PERS",    "PROC",      "RAISE",   "READONLY", "RECORD",   "RETRY",
                           "RETURN",    "STEP",    "SYSMODULE", "TEST",    "THEN",     "TO",       "TRAP",
                           "TRUE",      "TRYNEXT", "UNDO",      "VAR",     "VIEWONLY", "WHILE",    "WITH",
                           "XOR"}};
  return rules;
}

namespace {

// Why `name` is not a RAPID identifier (empty when it is one): RAPID's syntax and reserved words.
std::string identifierProblem(const std::string& name)
{
  const ProgramNameRules& rules = rapidNameRules();
  if (name.empty()) return "is empty";
  if (name.size() > rules.maxLength)
    return "has " + std::to_string(name.size()) + " characters; RAPID names have at most 32";
  if (!std::isalpha(static_cast<unsigned char>(name[0]))) return "does not start with a letter";
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_') || static_cast<unsigned char>(c) > 127)
      return "holds '" + std::string(1, c) + "'; RAPID names take letters, digits and '_' only";
  if (std::find(rules.reserved.begin(), rules.reserved.end(), upper(name)) != rules.reserved.end())
    return "is a RAPID reserved word";
  return {};
}

}  // namespace

bool isRapidIdentifier(const std::string& name)
{
  return identifierProblem(name).empty();
}

std::string rapidDataNameProblem(const std::string& name)
{
  if (std::string problem = identifierProblem(name); !problem.empty()) return problem;
  for (const char* predefined : {"TOOL0", "WOBJ0", "LOAD0", "FINE", "VMAX", "MAIN", "PAPPROACH", "PRETRACT"})
    if (upper(name) == predefined) return "is a name the controller or this program already uses";
  for (const char* prefix : {"v", "z", "p"})
    if (prefixAndDigits(name, prefix))
      return "looks like a predefined speed or zone (v100, z1) or a target of this program (p12)";
  return {};
}

std::string rapidModuleName(const std::string& wanted)
{
  return sanitizeProgramName(wanted, rapidNameRules());
}

}  // namespace spira
