#include "cli_common.h"

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/planning/settings_sections.h"

namespace spira::cli {

bool Args::takeSwitch(const std::string& name)
{
  for (auto it = rest.begin(); it != rest.end(); ++it) {
    if (*it == name) {
      rest.erase(it);
      return true;
    }
  }
  return false;
}

std::string Args::takeOption(const std::string& name)
{
  for (auto it = rest.begin(); it != rest.end(); ++it) {
    if (*it == name) {
      if (it + 1 == rest.end())
        throw UsageError("option " + name + " needs a value", "write " + name + " VALUE");
      std::string v = *(it + 1);
      rest.erase(it, it + 2);
      return v;
    }
    if (it->rfind(name + "=", 0) == 0) {
      std::string v = it->substr(name.size() + 1);
      rest.erase(it);
      return v;
    }
  }
  return {};
}

std::vector<std::string> Args::finish(const std::string& command, size_t minCount, size_t maxCount) const
{
  std::vector<std::string> positional;
  for (const auto& a : rest) {
    if (a.rfind("-", 0) == 0 && a != "-")
      throw UsageError("unknown option '" + a + "' for '" + command + "'",
                       "run 'spira-cli " + command + " --help' for the list of options");
    positional.push_back(a);
  }
  if (positional.size() < minCount)
    throw UsageError("'" + command + "' needs " + std::to_string(minCount) + " argument(s)",
                     "run 'spira-cli " + command + " --help'");
  if (positional.size() > maxCount)
    throw UsageError("too many arguments for '" + command + "': '" + positional[maxCount] + "'",
                     "run 'spira-cli " + command + " --help'");
  return positional;
}

Args splitArgs(const std::vector<std::string>& args)
{
  Args a;
  a.rest = args;
  return a;
}

std::vector<std::string> takeParamFlags(const std::vector<std::string>& rest,
                                        const std::vector<FlagTarget>& targets)
{
  try {
    return consumeParamFlags(rest, targets);
  } catch (const InputError& e) {
    throw UsageError(e.what(), e.hint());
  }
}

double finiteNumberFlag(const std::string& flag, const std::string& text, const std::string& example)
{
  std::string problem;
  const auto x = parseFiniteNumber(text, problem);
  if (!x) throw UsageError(flag + ": '" + clippedText(text) + "' " + problem, example);
  return *x;
}

long long wholeNumberFlag(const std::string& flag, const std::string& text, long long min, long long max,
                          const std::string& example)
{
  std::string problem;
  const auto n = parseWholeNumber(text, problem);
  if (n && (*n < min || *n > max))
    problem = "is out of range (" + std::to_string(min) + " to " + std::to_string(max) + ")";
  if (!n || *n < min || *n > max)
    throw UsageError(flag + ": '" + clippedText(text) + "' " + problem, example);
  return *n;
}

PlanFlags::PlanFlags(const PluginRegistry& registry)
{
  for (const SettingsSection& s : planSections()) values[std::string(s.name)];
  std::vector<const Plugin*> plugins = registry.ofKind(PluginKind::Decomposer);
  for (const Plugin* p : registry.ofKind(PluginKind::ClosureFinder)) plugins.push_back(p);
  for (const Plugin* p : plugins) values[p->id()];
  for (const SettingsSection& s : planSections())
    targets.push_back(FlagTarget{std::string(s.name), &s.schema, &values[std::string(s.name)]});
  for (const Plugin* p : plugins) targets.push_back(FlagTarget{p->id(), &p->schema(), &values[p->id()]});
}

double positiveFlag(const std::string& flag, const std::string& text, double fallback, bool zeroAllowed)
{
  if (text.empty()) return fallback;
  const double v = finiteNumberFlag(flag, text, flag + " 0.5");
  if (v < 0.0 || (!zeroAllowed && v == 0.0))
    throw UsageError(
        flag + " " + text + " is " + (zeroAllowed ? "negative" : "not above zero"),
        "give a number " + std::string(zeroAllowed ? "from 0" : "above 0") + ", e.g. " + flag + " 0.5");
  return v;
}

}  // namespace spira::cli
