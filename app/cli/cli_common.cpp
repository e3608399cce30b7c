#include "cli_common.h"

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

}  // namespace spira::cli
