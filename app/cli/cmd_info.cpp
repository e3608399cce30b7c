#include <iomanip>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "part_loading.h"
#include "spira/base/units.h"
#include "spira/io/import_service.h"
#include "spira/plugin/param_cli.h"
#include "spira/plugin/plugin_registry.h"

namespace spira::cli {
namespace {

void printTiming(const ImportedPart& part, std::ostream& out)
{
  out << std::fixed << std::setprecision(3) << "timing: read " << part.seconds.read << " s, weld "
      << part.seconds.weld << " s, validate " << part.seconds.validate << " s, total " << part.seconds.total()
      << " s\n";
}

}  // namespace

int cmdInfo(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  ImporterFlags flags(registry);
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout
        << "usage: spira-cli info PART [--json] [--timing] [importer flags]\n\n"
           "Imports PART (welded and validated as in the GUI) and prints mesh statistics, validation\n"
           "findings with positions, boundary loops (count, length, z-range), connected components and\n"
           "the open/closed classification. --json prints the same as JSON; --timing adds stage times.\n"
        << paramFlagsHelp(flags.targets());
    return kOk;
  }
  const bool json = args.takeSwitch("--json");
  const bool timing = args.takeSwitch("--timing");
  args.rest = consumeParamFlags(args.rest, flags.targets());
  const auto positional = args.finish("info", 1, 1);
  const std::string& file = positional[0];

  NullProgress progress;
  const ImportedPart part = flags.import(file, progress);

  if (json) {
    nlohmann::json j = part.report.toJson();
    j["file"] = file;
    j["importer"] = part.importerId;
    j["source_unit"] = std::string(lengthUnitSymbol(part.sourceUnit));
    j["weld"] = {{"input_vertices", part.weld.inputVertices},
                 {"output_vertices", part.weld.outputVertices},
                 {"tolerance_mm", part.weld.tolerance}};
    j["warnings"] = part.warnings;
    if (timing)
      j["timings_s"] = {{"read", part.seconds.read},
                        {"weld", part.seconds.weld},
                        {"validate", part.seconds.validate},
                        {"total", part.seconds.total()}};
    std::cout << j.dump(2) << "\n";
    return kOk;
  }
  std::cout << "file: " << file << " (" << part.importerId << ", coordinates in "
            << lengthUnitSymbol(part.sourceUnit) << ", shown in mm)\n";
  std::cout << "welded " << part.weld.inputVertices << " -> " << part.weld.outputVertices
            << " vertices (tolerance " << part.weld.tolerance << " mm)\n";
  std::cout << part.report.toText();
  for (const auto& w : part.warnings) std::cout << "warning: " << w << "\n";
  if (timing) printTiming(part, std::cout);
  return kOk;
}

}  // namespace spira::cli
