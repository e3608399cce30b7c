#include "spira/plugin/parameter.h"

namespace spira {
namespace {

ParamDef described(std::string key, ParamType type, ParamValue defaultValue, ParamText text)
{
  ParamDef d;
  d.key = std::move(key);
  d.type = type;
  d.defaultValue = std::move(defaultValue);
  d.label = std::move(text.label);
  d.tooltip = std::move(text.tooltip);
  d.category = std::move(text.category);
  return d;
}

}  // namespace

ParamDef numberParam(std::string key, double defaultValue, double min, double max, std::string unit,
                     ParamText text)
{
  ParamDef d = described(std::move(key), ParamType::Double, defaultValue, std::move(text));
  d.min = min;
  d.max = max;
  d.unit = std::move(unit);
  return d;
}

ParamDef integerParam(std::string key, std::int64_t defaultValue, std::int64_t min, std::int64_t max,
                      ParamText text)
{
  ParamDef d = described(std::move(key), ParamType::Int, defaultValue, std::move(text));
  d.min = static_cast<double>(min);
  d.max = static_cast<double>(max);
  return d;
}

ParamDef choiceParam(std::string key, std::string defaultValue, std::vector<std::string> choices,
                     ParamText text)
{
  ParamDef d = described(std::move(key), ParamType::Choice, std::move(defaultValue), std::move(text));
  d.choices = std::move(choices);
  return d;
}

ParamDef flagParam(std::string key, bool defaultValue, ParamText text)
{
  return described(std::move(key), ParamType::Bool, defaultValue, std::move(text));
}

ParamDef textParam(std::string key, std::string defaultValue, ParamText text)
{
  return described(std::move(key), ParamType::String, std::move(defaultValue), std::move(text));
}

ParamDef pathParam(std::string key, ParamText text)
{
  return described(std::move(key), ParamType::Path, std::string(), std::move(text));
}

}  // namespace spira
