#pragma once

#include <map>
#include <string>
#include <vector>

#include "spira/io/import_service.h"
#include "spira/plugin/param_cli.h"
#include "spira/plugin/plugin_registry.h"

namespace spira::cli {

// Importer flags: every importer's schema is a flag target, so "--unit m" or
// "--linear-deflection 0.05" are understood before we know which importer the file needs.
class ImporterFlags {
 public:
  explicit ImporterFlags(const PluginRegistry& registry);
  ImporterFlags(const ImporterFlags&) = delete;
  ImporterFlags& operator=(const ImporterFlags&) = delete;
  const std::vector<FlagTarget>& targets() const { return targets_; }
  // Imports `file` with the values given for its importer.
  ImportedPart import(const std::string& file, Progress& progress);

 private:
  const PluginRegistry& registry_;
  std::map<std::string, ParamSet> values_;
  std::vector<FlagTarget> targets_;
};

}  // namespace spira::cli
