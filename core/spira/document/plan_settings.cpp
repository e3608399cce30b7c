#include "spira/document/plan_settings.h"

#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/io/json_codec.h"

namespace spira {

namespace {
constexpr int kPlanSchema = 1;
}

ParamSet PlanSettings::section(const std::string& name) const
{
  auto it = params.find(name);
  return it == params.end() ? ParamSet() : it->second;
}

bool PlanSettings::operator==(const PlanSettings& o) const
{
  if (decomposerId != o.decomposerId || closureFinderId != o.closureFinderId) return false;
  // A section stored empty means the same as no section: every key takes its default.
  for (const auto& [name, values] : params)
    if (o.section(name) != values) return false;
  for (const auto& [name, values] : o.params)
    if (section(name) != values) return false;
  return true;
}

nlohmann::json planSettingsToJson(const PlanSettings& s)
{
  nlohmann::json j;
  j["schema"] = kPlanSchema;
  j["decomposer"] = s.decomposerId;
  j["closure_finder"] = s.closureFinderId;
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [section, values] : s.params) params[section] = values.toJson();
  j["params"] = std::move(params);
  return j;
}

PlanSettings planSettingsFromJson(const nlohmann::json& j)
{
  const std::string what = "plan settings";
  codec::checkSchema(j, kPlanSchema, what);
  PlanSettings s;
  s.decomposerId = codec::stringField(j, "decomposer", what);
  s.closureFinderId = codec::stringField(j, "closure_finder", what);
  const auto& params = codec::field(j, "params", what);
  if (!params.is_object())
    throw InputError(what + ": 'params' is not an object", "the project file is damaged");
  for (auto it = params.begin(); it != params.end(); ++it)
    s.params[it.key()] = ParamSet::fromJson(it.value());
  return s;
}

}  // namespace spira
