#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace spira {

enum class ParamType { Bool, Int, Double, String, Choice, Path };
const char* paramTypeName(ParamType t);  // "bool", "int", "double", "string", "choice", "path"

// A parameter value. Int and Double values are in the unit the definition declares (the unit
// the user sees); ParamSet::internal() converts to Spira's internal units.
using ParamValue = std::variant<bool, std::int64_t, double, std::string>;

// One parameter, declared once by its plugin and consumed by the GUI (panels), the CLI (flags
// and help) and the project file (values stored by key).
struct ParamDef {
  std::string key;  // snake_case, stable, persisted
  ParamType type = ParamType::Double;
  ParamValue defaultValue;
  std::optional<double> min, max;    // inclusive bounds for Int and Double
  std::string unit;                  // shown unit: "mm", "deg", "mm/s", "m/min", "%", "" ...
  std::string label;                 // short title-case label
  std::string tooltip;               // one or two sentences: what it does and when to change it
  std::string category;              // panel group, e.g. "Process window", "Discretisation"
  std::vector<std::string> choices;  // for Choice: the allowed values
};

// What a parameter shows the user: its label, tooltip and panel group (see ParamDef).
struct ParamText {
  std::string label;
  std::string tooltip;
  std::string category;
};

// The one way to declare a parameter: each builder fills the fields its type uses.
ParamDef numberParam(std::string key, double defaultValue, double min, double max, std::string unit,
                     ParamText text);
ParamDef integerParam(std::string key, std::int64_t defaultValue, std::int64_t min, std::int64_t max,
                      ParamText text);
ParamDef choiceParam(std::string key, std::string defaultValue, std::vector<std::string> choices,
                     ParamText text);
ParamDef flagParam(std::string key, bool defaultValue, ParamText text);
ParamDef textParam(std::string key, std::string defaultValue, ParamText text);
// A file path, empty by default.
ParamDef pathParam(std::string key, ParamText text);

class ParamSet;

// The ordered list of a plugin's parameters.
class ParamSchema {
 public:
  ParamSchema() = default;
  explicit ParamSchema(std::vector<ParamDef> defs);

  const std::vector<ParamDef>& defs() const { return defs_; }
  const ParamDef* find(const std::string& key) const;
  bool empty() const { return defs_.empty(); }

  ParamSet defaults() const;
  // Throws InputError naming the key, the value and the allowed range or choices.
  void validate(const ParamSet& values) const;
  // Parses a text value (CLI flag, preset file) for `key`; throws InputError when it does not fit.
  ParamValue parse(const std::string& key, const std::string& text) const;
  // Checks the schema itself (snake_case unique keys, defaults inside bounds, choices...);
  // returns the problems found, empty when sound. Used by the plugin contract tests.
  std::vector<std::string> selfCheck() const;

  nlohmann::json toJson() const;

 private:
  std::vector<ParamDef> defs_;
};

// Values by key. Missing keys fall back to the schema default when read through a schema.
class ParamSet {
 public:
  void set(const std::string& key, ParamValue v) { values_[key] = std::move(v); }
  bool has(const std::string& key) const { return values_.count(key) != 0; }
  void erase(const std::string& key) { values_.erase(key); }
  const std::map<std::string, ParamValue>& values() const { return values_; }

  // Typed getters. Int is readable as double. Throw InternalError on a missing key or wrong type.
  bool getBool(const std::string& key) const;
  std::int64_t getInt(const std::string& key) const;
  double getDouble(const std::string& key) const;
  const std::string& getString(const std::string& key) const;
  // The value converted to internal units (mm, rad, s, mm/s) using the unit the schema declares.
  double internal(const ParamSchema& schema, const std::string& key) const;

  // This set completed with `schema`'s defaults for every missing key.
  ParamSet withDefaults(const ParamSchema& schema) const;

  nlohmann::json toJson() const;
  static ParamSet fromJson(const nlohmann::json& j, const ParamSchema* schema = nullptr);

  bool operator==(const ParamSet& o) const { return values_ == o.values_; }
  bool operator!=(const ParamSet& o) const { return !(*this == o); }

 private:
  std::map<std::string, ParamValue> values_;
};

std::string paramValueToString(const ParamValue& v);

// True for a snake_case word: a lowercase letter, then lowercase letters, digits or '_'.
bool isSnakeCaseWord(const std::string& s);

}  // namespace spira
