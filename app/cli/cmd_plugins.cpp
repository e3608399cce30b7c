#include <iostream>

#include <nlohmann/json.hpp>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "spira/plugin/param_cli.h"
#include "spira/plugin/plugin_registry.h"

namespace spira::cli {

int cmdPlugins(const std::vector<std::string>& argv)
{
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout << "usage: spira-cli plugins [--json]\n\n"
                 "Lists every plugin with its full parameter schema (key, type, default, range, unit).\n";
    return kExitOk;
  }
  const bool json = args.takeSwitch("--json");
  args.finish("plugins", 0, 0);

  const PluginRegistry& registry = builtinRegistry();
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& p : registry.all()) {
      nlohmann::json j;
      j["id"] = p->id();
      j["kind"] = pluginKindName(p->kind());
      j["label"] = p->label();
      j["description"] = p->description();
      if (p->kind() == PluginKind::Importer)
        j["extensions"] = static_cast<const ImporterPlugin&>(*p).extensions();
      j["parameters"] = p->schema().toJson();
      out.push_back(j);
    }
    std::cout << out.dump(2) << "\n";
    return kExitOk;
  }
  for (const auto& p : registry.all()) {
    std::cout << p->id() << "  (" << pluginKindName(p->kind()) << ")  " << p->label() << "\n    "
              << p->description() << "\n";
    if (p->kind() == PluginKind::Importer) {
      std::cout << "    extensions:";
      for (const auto& e : static_cast<const ImporterPlugin&>(*p).extensions()) std::cout << " ." << e;
      std::cout << "\n";
    }
    ParamSet dummy;
    const std::string help = paramFlagsHelp({FlagTarget{p->id(), &p->schema(), &dummy}});
    if (!help.empty()) std::cout << help.substr(help.find('\n', 1) + 1);
    std::cout << "\n";
  }
  return kExitOk;
}

}  // namespace spira::cli
