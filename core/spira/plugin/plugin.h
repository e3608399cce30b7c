#pragma once

#include <string>

#include "spira/plugin/parameter.h"

namespace spira {

enum class PluginKind { Importer, Decomposer, ClosureFinder, Exporter };
const char* pluginKindName(PluginKind k);  // "importer", "decomposer", "closure", "exporter"

// What every plugin declares once. run-style methods of the derived interfaces take const
// inputs, return values, show no dialog, write no global state, are reentrant, report progress
// and honour cancellation through Progress, and return recoverable problems as warnings.
class Plugin {
 public:
  virtual ~Plugin() = default;
  virtual PluginKind kind() const = 0;
  virtual std::string id() const = 0;     // dotted lowercase: "decomposer.isovalue", "export.krl"
  virtual std::string label() const = 0;  // shown in menus
  virtual std::string description() const = 0;
  virtual const ParamSchema& schema() const = 0;
};

}  // namespace spira
