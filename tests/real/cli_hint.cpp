#include "real/cli_hint.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace spira::test::real {
namespace {

std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string trim(const std::string& s)
{
  const auto a = s.find_first_not_of(" \t");
  const auto b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// Verbs a hint opens with: it asks the user to do something.
bool opensWithImperative(const std::string& text)
{
  static const char* verbs[] = {"set",    "use",     "choose", "check",   "repair",   "fill",   "import",
                                "export", "try",     "lower",  "raise",   "widen",    "reduce", "increase",
                                "give",   "pass",    "run",    "make",    "remove",   "split",  "add",
                                "move",   "scale",   "place",  "turn",    "cut",      "close",  "select",
                                "pick",   "write",   "plan",   "keep",    "narrow",   "open",   "drop",
                                "rotate", "extract", "offset", "thicken", "re-export"};
  std::istringstream s(lower(text));
  std::string first;
  s >> first;
  for (const char* v : verbs)
    if (first == v) return true;
  return false;
}

}  // namespace

std::vector<std::string> actionableHints(const std::string& output)
{
  std::vector<std::string> hints;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    const std::string l = lower(trim(line));
    const bool labelled = l.rfind("hint:", 0) == 0 || l.rfind("advice:", 0) == 0;
    if (labelled && opensWithImperative(trim(line.substr(line.find(':') + 1)))) {
      hints.push_back(trim(line));
      continue;
    }
    if (l.rfind("try ", 0) == 0) {
      hints.push_back(trim(line));
      continue;
    }
    // "spira-cli: what (hint)": the last parenthesised clause of an error line.
    if (l.rfind("spira-cli:", 0) == 0 && !line.empty() && trim(line).back() == ')') {
      const std::string t = trim(line);
      int depth = 0;
      for (size_t k = t.size(); k-- > 0;) {
        if (t[k] == ')') ++depth;
        if (t[k] == '(' && --depth == 0) {
          const std::string clause = t.substr(k + 1, t.size() - k - 2);
          // A hint may list several actions: any of them opening with a verb counts.
          std::istringstream parts(clause);
          std::string part;
          bool any = false;
          while (std::getline(parts, part, ';')) any = any || opensWithImperative(trim(part));
          if (any) hints.push_back(clause);
          break;
        }
      }
    }
  }
  return hints;
}

bool hasActionableHint(const std::string& output)
{
  return !actionableHints(output).empty();
}

bool mentionsAny(const std::string& text, const std::vector<std::string>& words)
{
  const std::string t = lower(text);
  for (const auto& w : words)
    if (t.find(lower(w)) != std::string::npos) return true;
  return false;
}

}  // namespace spira::test::real
