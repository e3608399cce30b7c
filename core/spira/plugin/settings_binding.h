#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/plugin/parameter.h"

namespace spira {

// A settings struct `S` and the parameters that fill it, declared together: each entry is one
// ParamDef (key, default, bounds, unit, text) and the field it is read into. The schema the GUI,
// the CLI and the project file use is built from the entries, and read() fills an `S` from a
// ParamSet, so a key is written once. Rules that tie fields together (a default derived from
// another field, crossed limits) are not the binding's: the caller applies them after read().
template <class S>
class SettingsBinding {
 public:
  // How an entry writes its value (completed with the default, validated) into the struct.
  using Reader = std::function<void(S&, const ParamValue&)>;
  struct Entry {
    ParamDef def;
    Reader read;
  };

  explicit SettingsBinding(std::vector<Entry> entries)
      : entries_(std::move(entries)), schema_(defsOf(entries_))
  {
  }

  const ParamSchema& schema() const { return schema_; }

  // `values` completed with the schema's defaults and validated (InputError naming the key), then
  // read into `into`: fields without an entry keep their value.
  void read(const ParamSet& values, S& into) const
  {
    const ParamSet complete = values.withDefaults(schema_);
    schema_.validate(complete);
    for (const Entry& e : entries_) e.read(into, complete.values().at(e.def.key));
  }

  // A number shown in `def.unit`, stored in internal units (mm, rad, s, mm/s, fractions for %)
  // in the field `field` names: a data-member pointer or a callable S& -> double&.
  template <class Field>
  static Entry number(ParamDef def, Field field)
  {
    const double factor = toInternalFactor(def.unit);
    return {std::move(def),
            [field, factor](S& s, const ParamValue& v) { std::invoke(field, s) = numberOf(v) * factor; }};
  }

  template <class Field>
  static Entry flag(ParamDef def, Field field)
  {
    return {std::move(def),
            [field](S& s, const ParamValue& v) { std::invoke(field, s) = std::get<bool>(v); }};
  }

  // A Choice read into an enum: `values` pairs each allowed text with its value, in the order the
  // user sees them; `defaultText` is one of the texts. `field` is a data member of S or of a base.
  template <class E, class Owner>
  static Entry choice(std::string key, std::string defaultText, std::vector<std::pair<std::string, E>> values,
                      ParamText text, E Owner::*field)
  {
    std::vector<std::string> texts;
    for (const auto& value : values) texts.push_back(value.first);
    return {choiceParam(std::move(key), std::move(defaultText), std::move(texts), std::move(text)),
            [field, values](S& s, const ParamValue& v) {
              const std::string& chosen = std::get<std::string>(v);
              for (const auto& [name, value] : values)
                if (name == chosen) {
                  std::invoke(field, s) = value;
                  return;
                }
              throw InternalError("choice '" + chosen + "' has no value");
            }};
  }

  // A string or path, stored as written.
  template <class Field>
  static Entry text(ParamDef def, Field field)
  {
    return {std::move(def),
            [field](S& s, const ParamValue& v) { std::invoke(field, s) = std::get<std::string>(v); }};
  }

 private:
  static double numberOf(const ParamValue& v)
  {
    if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
    return std::get<double>(v);
  }

  static std::vector<ParamDef> defsOf(const std::vector<Entry>& entries)
  {
    std::vector<ParamDef> defs;
    for (const Entry& e : entries) defs.push_back(e.def);
    return defs;
  }

  std::vector<Entry> entries_;
  ParamSchema schema_;
};

}  // namespace spira
