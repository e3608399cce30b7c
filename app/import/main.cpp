// spira-import: the helper process that runs a third-party importer (OpenCASCADE) for spira and
// spira-cli, so that a crash in it cannot take them down. See core/spira/io/isolated_import.h.
// It registers only the importers that run isolated: every library it does not load is start-up
// time saved on each import.
#include "spira/io/isolated_import.h"
#include "spira/plugin/plugin_registry.h"

void spira_register_import_cad(spira::PluginRegistry& registry);

int main(int argc, char** argv)
{
  spira::PluginRegistry registry;
  spira_register_import_cad(registry);
  return spira::importHelperMain(argc, argv, registry);
}
