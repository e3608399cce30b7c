#include "spira/export/program_names.h"

#include <algorithm>
#include <cctype>

namespace spira {

namespace {

bool isAsciiAlnum(char c)
{
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
}

std::string upper(std::string s)
{
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

void trimUnderscores(std::string& s)
{
  while (!s.empty() && s.back() == '_') s.pop_back();
  size_t lead = 0;
  while (lead < s.size() && s[lead] == '_') ++lead;
  s.erase(0, lead);
}

bool isReserved(const std::string& name, const ProgramNameRules& rules)
{
  const std::string u = upper(name);
  return std::find(rules.reserved.begin(), rules.reserved.end(), u) != rules.reserved.end();
}

}  // namespace

const ProgramNameRules& krlNameRules()
{
  static const ProgramNameRules rules{
      24, false, "SPIRA", {"AND",      "ANIN",      "ANOUT",  "AXIS",   "B_AND",   "B_EXOR",    "B_NOT",
                           "B_OR",     "BOOL",      "BRAKE",  "CASE",   "CHAR",    "CIRC",      "CIRC_REL",
                           "CONST",    "CONTINUE",  "DECL",   "DEF",    "DEFAULT", "DEFDAT",    "DEFFCT",
                           "DELAY",    "DISTANCE",  "DO",     "E6AXIS", "E6POS",   "ELSE",      "END",
                           "ENDDAT",   "ENDFCT",    "ENDFOR", "ENDIF",  "ENDLOOP", "ENDSPLINE", "ENDSWITCH",
                           "ENDWHILE", "ENUM",      "EXIT",   "EXOR",   "EXT",     "EXTFCT",    "FALSE",
                           "FOR",      "FRAME",     "GLOBAL", "GOTO",   "HALT",    "IF",        "IMPORT",
                           "INT",      "INTERRUPT", "IS",     "LIN",    "LIN_REL", "LOOP",      "NOT",
                           "OR",       "POS",       "PRIO",   "PTP",    "PTP_REL", "PUBLIC",    "PULSE",
                           "REAL",     "REPEAT",    "RESUME", "RETURN", "SCIRC",   "SEC",       "SIGNAL",
                           "SLIN",     "SPLINE",    "SPTP",   "STEP",   "STRUC",   "SWITCH",    "THEN",
                           "TO",       "TRIGGER",   "TRUE",   "UNTIL",  "WAIT",    "WHEN",      "WHILE"}};
  return rules;
}

const ProgramNameRules& fanucNameRules()
{
  static const ProgramNameRules rules{
      36, true, "SPIRA", {"ABORT", "CALL", "END", "JMP", "LBL", "PAUSE", "RUN", "SELECT", "WAIT"}};
  return rules;
}

std::string sanitizeProgramName(std::string_view wanted, const ProgramNameRules& rules)
{
  std::string s;
  s.reserve(wanted.size());
  for (char c : wanted) {
    const char mapped = isAsciiAlnum(c) ? c : '_';
    if (mapped == '_' && !s.empty() && s.back() == '_') continue;
    s.push_back(mapped);
  }
  trimUnderscores(s);
  if (rules.uppercase) s = upper(s);
  if (s.empty()) s = rules.fallback;
  if (s[0] >= '0' && s[0] <= '9') s.insert(0, "P");
  const size_t limit = std::max<size_t>(rules.maxLength, 1);
  if (s.size() > limit) {
    s.resize(limit);
    trimUnderscores(s);
  }
  if (isReserved(s, rules)) {
    const std::string suffix = "_PRG";
    if (s.size() + suffix.size() > limit) s.resize(limit > suffix.size() ? limit - suffix.size() : 1);
    s += suffix;
  }
  return s;
}

ProgramNames splitProgramNames(std::string_view wanted, size_t partCount, const ProgramNameRules& rules)
{
  ProgramNames names;
  names.main = sanitizeProgramName(wanted, rules);
  if (partCount == 0) return names;
  size_t digits = 3;
  for (size_t n = partCount; n >= 1000; n /= 10) ++digits;
  const size_t suffixLength = 1 + digits;
  ProgramNameRules baseRules = rules;
  baseRules.maxLength = rules.maxLength > suffixLength ? rules.maxLength - suffixLength : 1;
  baseRules.reserved.clear();  // "END_001" is not a keyword
  const std::string base = sanitizeProgramName(names.main, baseRules);
  for (size_t i = 1; i <= partCount; ++i) {
    std::string number = std::to_string(i);
    number.insert(0, digits - number.size(), '0');
    names.parts.push_back(base + "_" + number);
  }
  return names;
}

}  // namespace spira
