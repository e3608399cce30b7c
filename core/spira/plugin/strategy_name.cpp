#include "spira/plugin/strategy_name.h"

namespace spira {
namespace {

constexpr const char* kPrefix = "decomposer.";

bool hasPrefix(const std::string& s)
{
  return s.rfind(kPrefix, 0) == 0;
}

}  // namespace

std::string strategyName(const std::string& strategyOrId)
{
  return hasPrefix(strategyOrId) ? strategyOrId.substr(std::string(kPrefix).size()) : strategyOrId;
}

std::string decomposerIdOf(const std::string& strategyOrId)
{
  return hasPrefix(strategyOrId) ? strategyOrId : kPrefix + strategyOrId;
}

}  // namespace spira
