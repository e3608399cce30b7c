#pragma once

#include <memory>
#include <string>
#include <vector>

#include "spira/plugin/closure_finder.h"
#include "spira/plugin/decomposer.h"
#include "spira/plugin/exporter.h"
#include "spira/plugin/importer.h"

namespace spira {

// Owns plugins and finds them by id, kind or file extension. Built-in plugins are added at
// start-up (see plugins/builtin_plugins.h); ids are unique.
class PluginRegistry {
 public:
  // Throws InternalError on a duplicate or malformed id.
  void add(std::unique_ptr<Plugin> plugin);

  const std::vector<std::unique_ptr<Plugin>>& all() const { return plugins_; }
  const Plugin* find(const std::string& id) const;
  std::vector<const Plugin*> ofKind(PluginKind kind) const;

  // Throws InputError listing the available ids when `id` is unknown or of another kind.
  const ImporterPlugin& importer(const std::string& id) const;
  const DecomposerPlugin& decomposer(const std::string& id) const;
  const ClosureFinderPlugin& closureFinder(const std::string& id) const;
  const ExporterPlugin& exporter(const std::string& id) const;

  // The importer for a file name's extension (case-insensitive); throws InputError listing the
  // supported extensions when none matches.
  const ImporterPlugin& importerForFile(const std::string& fileName) const;
  std::vector<std::string> importExtensions() const;

 private:
  template <class T>
  const T& typed(const std::string& id, PluginKind kind) const;
  std::vector<std::unique_ptr<Plugin>> plugins_;
};

// The exporter a format name stands for: "krl", "rapid", "gcode" (its id without "export.") or a full id
// ("export.krl"); null for anything else.
const ExporterPlugin* exporterForFormat(const PluginRegistry& registry, const std::string& format);
// The format names of the registered exporters, "krl, fanuc_tp, ...", for the message that refuses one.
std::string exporterFormatList(const PluginRegistry& registry);

// True for a valid plugin id: dotted lowercase words, e.g. "export.fanuc_tp".
bool isValidPluginId(const std::string& id);

}  // namespace spira
