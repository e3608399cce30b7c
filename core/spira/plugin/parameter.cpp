#include "spira/plugin/parameter.h"

#include <cmath>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/base/units.h"

namespace spira {
namespace {

std::string describeRange(const ParamDef& d)
{
  std::ostringstream s;
  if (d.min && d.max)
    s << "between " << *d.min << " and " << *d.max;
  else if (d.min)
    s << "at least " << *d.min;
  else if (d.max)
    s << "at most " << *d.max;
  if (!d.unit.empty()) s << " " << d.unit;
  return s.str();
}

std::string useHint(const std::string& kind, const ParamDef& d)
{
  return "use " + kind + (d.min || d.max ? " " + describeRange(d) : std::string());
}

std::string joinChoices(const std::vector<std::string>& c)
{
  std::string out;
  for (const auto& x : c) out += (out.empty() ? "" : ", ") + x;
  return out;
}

bool typeMatches(ParamType t, const ParamValue& v)
{
  switch (t) {
    case ParamType::Bool:
      return std::holds_alternative<bool>(v);
    case ParamType::Int:
      return std::holds_alternative<std::int64_t>(v);
    case ParamType::Double:
      return std::holds_alternative<double>(v) || std::holds_alternative<std::int64_t>(v);
    case ParamType::String:
    case ParamType::Choice:
    case ParamType::Path:
      return std::holds_alternative<std::string>(v);
  }
  return false;
}

double numeric(const ParamValue& v)
{
  if (const auto* d = std::get_if<double>(&v)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  return 0.0;
}

}  // namespace

const char* paramTypeName(ParamType t)
{
  switch (t) {
    case ParamType::Bool:
      return "bool";
    case ParamType::Int:
      return "int";
    case ParamType::Double:
      return "double";
    case ParamType::String:
      return "string";
    case ParamType::Choice:
      return "choice";
    case ParamType::Path:
      return "path";
  }
  return "unknown";
}

bool isSnakeCaseWord(const std::string& s)
{
  if (s.empty() || s[0] < 'a' || s[0] > 'z') return false;
  for (char c : s)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

std::string paramValueToString(const ParamValue& v)
{
  if (const auto* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&v)) {
    std::ostringstream s;
    s.precision(15);
    s << *d;
    return s.str();
  }
  return std::get<std::string>(v);
}

ParamSchema::ParamSchema(std::vector<ParamDef> defs) : defs_(std::move(defs)) {}

const ParamDef* ParamSchema::find(const std::string& key) const
{
  for (const auto& d : defs_)
    if (d.key == key) return &d;
  return nullptr;
}

ParamSet ParamSchema::defaults() const
{
  ParamSet s;
  for (const auto& d : defs_) s.set(d.key, d.defaultValue);
  return s;
}

void ParamSchema::validate(const ParamSet& values) const
{
  for (const auto& [key, v] : values.values()) {
    const ParamDef* d = find(key);
    if (!d)
      throw InputError("unknown parameter '" + key + "'", "check the spelling against the plugin's schema");
    if (!typeMatches(d->type, v))
      throw InputError("parameter '" + key + "' must be of type " + paramTypeName(d->type),
                       "got '" + paramValueToString(v) + "'");
    if (d->type == ParamType::Int || d->type == ParamType::Double) {
      const double x = numeric(v);
      if (!std::isfinite(x))
        throw InputError("parameter '" + key + "' is not a finite number", "give a number");
      if ((d->min && x < *d->min) || (d->max && x > *d->max))
        throw InputError("parameter '" + key + "' = " + paramValueToString(v) + " is out of range",
                         "use a value " + describeRange(*d));
    }
    if (d->type == ParamType::Choice) {
      const auto& s = std::get<std::string>(v);
      if (std::find(d->choices.begin(), d->choices.end(), s) == d->choices.end())
        throw InputError("parameter '" + key + "' = '" + s + "' is not an allowed choice",
                         "use one of: " + joinChoices(d->choices));
    }
  }
}

ParamValue ParamSchema::parse(const std::string& key, const std::string& text) const
{
  const ParamDef* d = find(key);
  if (!d)
    throw InputError("unknown parameter '" + key + "'", "check the spelling against the plugin's schema");
  ParamValue v;
  switch (d->type) {
    case ParamType::Bool:
      if (text == "true" || text == "1" || text == "yes" || text == "on")
        v = true;
      else if (text == "false" || text == "0" || text == "no" || text == "off")
        v = false;
      else
        throw InputError("parameter '" + key + "' expects true or false", "got '" + clippedText(text) + "'");
      break;
    case ParamType::Int: {
      std::string problem;
      const auto x = parseWholeNumber(text, problem);
      if (!x)
        throw InputError("parameter '" + key + "': '" + clippedText(text) + "' " + problem,
                         useHint("a whole number", *d));
      v = static_cast<std::int64_t>(*x);
      break;
    }
    case ParamType::Double: {
      std::string problem;
      const auto x = parseFiniteNumber(text, problem);
      if (!x)
        throw InputError("parameter '" + key + "': '" + clippedText(text) + "' " + problem,
                         useHint("a number", *d));
      v = *x;
      break;
    }
    default:
      v = text;
      break;
  }
  ParamSet one;
  one.set(key, v);
  validate(one);
  return v;
}

std::vector<std::string> ParamSchema::selfCheck() const
{
  std::vector<std::string> problems;
  std::set<std::string> seen;
  for (const auto& d : defs_) {
    if (!isSnakeCaseWord(d.key)) problems.push_back("key '" + d.key + "' is not snake_case");
    if (!seen.insert(d.key).second) problems.push_back("key '" + d.key + "' declared twice");
    if (d.label.empty()) problems.push_back("key '" + d.key + "' has no label");
    if (d.tooltip.empty()) problems.push_back("key '" + d.key + "' has no tooltip");
    if (d.category.empty()) problems.push_back("key '" + d.key + "' has no category");
    if (!typeMatches(d.type, d.defaultValue) ||
        (d.type == ParamType::Double && !std::holds_alternative<double>(d.defaultValue)))
      problems.push_back("key '" + d.key + "' default does not match its type");
    if (d.min && d.max && *d.min > *d.max) problems.push_back("key '" + d.key + "' has min > max");
    if (d.type == ParamType::Choice && d.choices.empty())
      problems.push_back("key '" + d.key + "' has no choices");
    try {
      ParamSet one;
      one.set(d.key, d.defaultValue);
      validate(one);
    } catch (const Error& e) {
      problems.push_back("key '" + d.key + "' default is invalid: " + e.what());
    }
  }
  return problems;
}

nlohmann::json ParamSchema::toJson() const
{
  nlohmann::json arr = nlohmann::json::array();
  for (const auto& d : defs_) {
    nlohmann::json j;
    j["key"] = d.key;
    j["type"] = paramTypeName(d.type);
    j["default"] = nlohmann::json::parse(std::holds_alternative<std::string>(d.defaultValue)
                                             ? nlohmann::json(std::get<std::string>(d.defaultValue)).dump()
                                             : paramValueToString(d.defaultValue));
    j["min"] = d.min ? nlohmann::json(*d.min) : nlohmann::json(nullptr);
    j["max"] = d.max ? nlohmann::json(*d.max) : nlohmann::json(nullptr);
    j["unit"] = d.unit;
    j["label"] = d.label;
    j["tooltip"] = d.tooltip;
    j["category"] = d.category;
    if (d.type == ParamType::Choice) j["choices"] = d.choices;
    arr.push_back(j);
  }
  return arr;
}

bool ParamSet::getBool(const std::string& key) const
{
  auto it = values_.find(key);
  if (it == values_.end() || !std::holds_alternative<bool>(it->second))
    throw InternalError("parameter '" + key + "' missing or not a bool");
  return std::get<bool>(it->second);
}

std::int64_t ParamSet::getInt(const std::string& key) const
{
  auto it = values_.find(key);
  if (it == values_.end() || !std::holds_alternative<std::int64_t>(it->second))
    throw InternalError("parameter '" + key + "' missing or not an int");
  return std::get<std::int64_t>(it->second);
}

double ParamSet::getDouble(const std::string& key) const
{
  auto it = values_.find(key);
  if (it == values_.end()) throw InternalError("parameter '" + key + "' missing");
  if (const auto* d = std::get_if<double>(&it->second)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&it->second)) return static_cast<double>(*i);
  throw InternalError("parameter '" + key + "' is not numeric");
}

const std::string& ParamSet::getString(const std::string& key) const
{
  auto it = values_.find(key);
  if (it == values_.end() || !std::holds_alternative<std::string>(it->second))
    throw InternalError("parameter '" + key + "' missing or not a string");
  return std::get<std::string>(it->second);
}

double ParamSet::internal(const ParamSchema& schema, const std::string& key) const
{
  const ParamDef* d = schema.find(key);
  if (!d) throw InternalError("parameter '" + key + "' not in schema");
  const double v = has(key) ? getDouble(key) : numeric(d->defaultValue);
  return v * toInternalFactor(d->unit);
}

ParamSet ParamSet::withDefaults(const ParamSchema& schema) const
{
  ParamSet out = *this;
  for (const auto& d : schema.defs())
    if (!out.has(d.key)) out.set(d.key, d.defaultValue);
  return out;
}

nlohmann::json ParamSet::toJson() const
{
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [k, v] : values_) {
    if (const auto* b = std::get_if<bool>(&v))
      j[k] = *b;
    else if (const auto* i = std::get_if<std::int64_t>(&v))
      j[k] = *i;
    else if (const auto* d = std::get_if<double>(&v))
      j[k] = *d;
    else
      j[k] = std::get<std::string>(v);
  }
  return j;
}

ParamSet ParamSet::fromJson(const nlohmann::json& j, const ParamSchema* schema)
{
  if (!j.is_object()) throw InputError("parameter set is not a JSON object", "check the file");
  ParamSet s;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const ParamDef* d = schema ? schema->find(it.key()) : nullptr;
    const auto& v = it.value();
    if (v.is_boolean())
      s.set(it.key(), v.get<bool>());
    else if (v.is_number_integer() && !(d && d->type == ParamType::Double))
      s.set(it.key(), v.get<std::int64_t>());
    else if (v.is_number())
      s.set(it.key(), v.get<double>());
    else if (v.is_string())
      s.set(it.key(), v.get<std::string>());
    else
      throw InputError("parameter '" + it.key() + "' has an unsupported JSON type",
                       "use a bool, number or string");
  }
  if (schema) schema->validate(s);
  return s;
}

}  // namespace spira
