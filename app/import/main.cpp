// spira-import: the helper process that runs a third-party importer (OpenCASCADE for CAD parts,
// Assimp for robot link meshes) for spira and spira-cli, so that a crash in it cannot take them
// down. See core/spira/io/isolated_import.h. It registers only the importers that run isolated:
// every library it does not load is start-up time saved.
#include <memory>

#include "link_mesh_importer.h"
#include "spira/io/isolated_import.h"
#include "spira/plugin/plugin_registry.h"

void spira_register_import_cad(spira::PluginRegistry& registry);

#if defined(__SANITIZE_ADDRESS__)
// In a sanitizer build a crash inside OpenCASCADE ends the helper by its signal, as in a release
// build, instead of through AddressSanitizer's report and exit code 1: the parent names a crash by
// its signal, and that is what the hostile-file tests check. An allocation past the reader's memory
// limit fails as in a release build (null, then bad_alloc) instead of ending the process.
extern "C" __attribute__((used, visibility("default"))) const char* __asan_default_options()
{
  return "handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_sigill=0:allocator_may_return_null=1";
}
#endif

int main(int argc, char** argv)
{
  spira::PluginRegistry registry;
  spira_register_import_cad(registry);
  registry.add(std::make_unique<spira::LinkMeshImporter>());
  return spira::importHelperMain(argc, argv, registry);
}
