#include <memory>

#include "assimp_importer.h"
#include "ply_importer.h"
#include "spira/plugin/plugin_registry.h"
#include "stl_importer.h"

void spira_register_import_mesh(spira::PluginRegistry& registry)
{
  using spira::import_mesh::AssimpImporter;
  registry.add(std::make_unique<spira::import_mesh::StlImporter>());
  registry.add(std::make_unique<AssimpImporter>("import.obj", "Wavefront OBJ mesh", "OBJ",
                                                std::vector<std::string>{"obj"}));
  registry.add(std::make_unique<spira::import_mesh::PlyImporter>());
}
