#include "part_loading.h"

namespace spira::cli {

ImporterFlags::ImporterFlags(const PluginRegistry& registry) : registry_(registry)
{
  const auto importers = registry.ofKind(PluginKind::Importer);
  for (const Plugin* p : importers) values_[p->id()];
  for (const Plugin* p : importers) targets_.push_back(FlagTarget{p->id(), &p->schema(), &values_[p->id()]});
}

ImportedPart ImporterFlags::import(const std::string& file, Progress& progress)
{
  const ImporterPlugin& importer = registry_.importerForFile(file);
  return importPart(registry_, file, &values_[importer.id()], progress);
}

}  // namespace spira::cli
