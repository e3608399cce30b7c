#include "spira/plugin/param_cli.h"

#include <map>
#include <sstream>

#include "spira/base/error.h"

namespace spira {
namespace {

std::string valueHint(const ParamDef& d)
{
  switch (d.type) {
    case ParamType::Bool:
      return "";
    case ParamType::Int:
      return " N";
    case ParamType::Double:
      return d.unit.empty() ? " X" : " X[" + d.unit + "]";
    case ParamType::String:
      return " TEXT";
    case ParamType::Choice: {
      std::string c;
      for (const auto& x : d.choices) c += (c.empty() ? "" : "|") + x;
      return " " + c;
    }
    case ParamType::Path:
      return " FILE";
  }
  return "";
}

struct Match {
  const ParamDef* def = nullptr;
  std::vector<const FlagTarget*> targets;
};

std::map<std::string, Match> flagIndex(const std::vector<FlagTarget>& targets)
{
  std::map<std::string, Match> index;
  for (const auto& t : targets) {
    for (const auto& d : t.schema->defs()) {
      auto& m = index[flagForKey(d.key)];
      if (m.def && m.def->type != d.type)
        throw InternalError("parameter '" + d.key + "' has different types in " + m.targets.front()->owner +
                            " and " + t.owner);
      if (!m.def) m.def = &d;
      m.targets.push_back(&t);
    }
  }
  return index;
}

}  // namespace

std::string flagForKey(const std::string& key)
{
  std::string f = "--" + key;
  for (auto& c : f)
    if (c == '_') c = '-';
  return f;
}

std::vector<std::string> consumeParamFlags(const std::vector<std::string>& args,
                                           const std::vector<FlagTarget>& targets)
{
  const auto index = flagIndex(targets);
  std::vector<std::string> rest;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0) {
      rest.push_back(a);
      continue;
    }
    std::string name = a;
    std::string value;
    bool hasValue = false;
    if (const auto eq = a.find('='); eq != std::string::npos) {
      name = a.substr(0, eq);
      value = a.substr(eq + 1);
      hasValue = true;
    }
    bool negated = false;
    auto it = index.find(name);
    if (it == index.end() && name.rfind("--no-", 0) == 0) {
      auto neg = index.find("--" + name.substr(5));
      if (neg != index.end() && neg->second.def->type == ParamType::Bool) {
        it = neg;
        negated = true;
      }
    }
    if (it == index.end()) {
      rest.push_back(a);
      continue;
    }
    const ParamDef& d = *it->second.def;
    if (d.type == ParamType::Bool && !hasValue) {
      value = negated ? "false" : "true";
    } else if (!hasValue) {
      if (i + 1 >= args.size())
        throw InputError("flag " + name + " needs a value", "write " + name + valueHint(d));
      value = args[++i];
    }
    for (const FlagTarget* t : it->second.targets) t->values->set(d.key, t->schema->parse(d.key, value));
  }
  return rest;
}

std::string paramFlagsHelp(const std::vector<FlagTarget>& targets)
{
  std::ostringstream out;
  for (const auto& t : targets) {
    if (t.schema->empty()) continue;
    out << "\n" << t.owner << " parameters:\n";
    std::string category;
    for (const auto& d : t.schema->defs()) {
      if (d.category != category) {
        category = d.category;
        out << "  [" << category << "]\n";
      }
      out << "  " << flagForKey(d.key) << valueHint(d) << "\n      " << d.label << ". " << d.tooltip;
      const std::string byDefault = paramValueToString(d.defaultValue);
      out << " Default: " << (byDefault.empty() ? std::string("none") : byDefault)
          << (d.unit.empty() ? "" : " " + d.unit);
      if (d.min || d.max) {
        out << "; range ";
        out << (d.min ? paramValueToString(*d.min) : std::string("-inf")) << " .. "
            << (d.max ? paramValueToString(*d.max) : std::string("+inf"));
      }
      out << ".\n";
    }
  }
  return out.str();
}

}  // namespace spira
