#include "spira/plugin/plugin_registry.h"

#include <algorithm>
#include <cctype>

#include "spira/base/error.h"

namespace spira {

const char* pluginKindName(PluginKind k)
{
  switch (k) {
    case PluginKind::Importer:
      return "importer";
    case PluginKind::Decomposer:
      return "decomposer";
    case PluginKind::ClosureFinder:
      return "closure";
    case PluginKind::Exporter:
      return "exporter";
  }
  return "unknown";
}

bool isValidPluginId(const std::string& id)
{
  size_t words = 0, start = 0;
  while (start <= id.size()) {
    const size_t dot = std::min(id.find('.', start), id.size());
    if (!isSnakeCaseWord(id.substr(start, dot - start))) return false;
    ++words;
    start = dot + 1;
  }
  return words >= 2;
}

void PluginRegistry::add(std::unique_ptr<Plugin> plugin)
{
  if (!plugin) throw InternalError("null plugin registered");
  const std::string id = plugin->id();
  if (!isValidPluginId(id)) throw InternalError("plugin id '" + id + "' is not dotted lowercase");
  if (find(id)) throw InternalError("plugin id '" + id + "' registered twice");
  plugins_.push_back(std::move(plugin));
}

const Plugin* PluginRegistry::find(const std::string& id) const
{
  for (const auto& p : plugins_)
    if (p->id() == id) return p.get();
  return nullptr;
}

std::vector<const Plugin*> PluginRegistry::ofKind(PluginKind kind) const
{
  std::vector<const Plugin*> out;
  for (const auto& p : plugins_)
    if (p->kind() == kind) out.push_back(p.get());
  return out;
}

template <class T>
const T& PluginRegistry::typed(const std::string& id, PluginKind kind) const
{
  const Plugin* p = find(id);
  if (p && p->kind() == kind) return static_cast<const T&>(*p);
  std::string known;
  for (const Plugin* q : ofKind(kind)) known += (known.empty() ? "" : ", ") + q->id();
  throw InputError(std::string("unknown ") + pluginKindName(kind) + " '" + id + "'",
                   known.empty() ? std::string("none is available in this build") : "available: " + known);
}

const ImporterPlugin& PluginRegistry::importer(const std::string& id) const
{
  return typed<ImporterPlugin>(id, PluginKind::Importer);
}
const DecomposerPlugin& PluginRegistry::decomposer(const std::string& id) const
{
  return typed<DecomposerPlugin>(id, PluginKind::Decomposer);
}
const ClosureFinderPlugin& PluginRegistry::closureFinder(const std::string& id) const
{
  return typed<ClosureFinderPlugin>(id, PluginKind::ClosureFinder);
}
const ExporterPlugin& PluginRegistry::exporter(const std::string& id) const
{
  return typed<ExporterPlugin>(id, PluginKind::Exporter);
}

std::vector<std::string> PluginRegistry::importExtensions() const
{
  std::vector<std::string> exts;
  for (const Plugin* p : ofKind(PluginKind::Importer))
    for (const auto& e : static_cast<const ImporterPlugin*>(p)->extensions()) exts.push_back(e);
  std::sort(exts.begin(), exts.end());
  exts.erase(std::unique(exts.begin(), exts.end()), exts.end());
  return exts;
}

const ImporterPlugin& PluginRegistry::importerForFile(const std::string& fileName) const
{
  const auto dot = fileName.find_last_of('.');
  const auto slash = fileName.find_last_of("/\\");
  std::string ext;
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) ext = fileName.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const Plugin* p : ofKind(PluginKind::Importer)) {
    const auto* imp = static_cast<const ImporterPlugin*>(p);
    for (const auto& e : imp->extensions())
      if (e == ext) return *imp;
  }
  std::string list;
  for (const auto& e : importExtensions()) list += (list.empty() ? "." : ", .") + e;
  throw InputError("unsupported file type '" + (ext.empty() ? std::string("(no extension)") : "." + ext) +
                       "' for '" + fileName + "'",
                   "convert the part to one of: " + list);
}

const ExporterPlugin* exporterForFormat(const PluginRegistry& registry, const std::string& format)
{
  const std::string id = format.find('.') == std::string::npos ? "export." + format : format;
  const Plugin* p = registry.find(id);
  return p && p->kind() == PluginKind::Exporter ? &registry.exporter(id) : nullptr;
}

std::string exporterFormatList(const PluginRegistry& registry)
{
  std::string formats;
  for (const Plugin* e : registry.ofKind(PluginKind::Exporter))
    formats += (formats.empty() ? "" : ", ") + e->id().substr(e->id().find('.') + 1);
  return formats;
}

}  // namespace spira
