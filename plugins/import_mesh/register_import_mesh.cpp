#include <memory>

#include "obj_importer.h"
#include "ply_importer.h"
#include "spira/plugin/plugin_registry.h"
#include "stl_importer.h"

void spira_register_import_mesh(spira::PluginRegistry& registry)
{
  registry.add(std::make_unique<spira::import_mesh::StlImporter>());
  registry.add(std::make_unique<spira::import_mesh::ObjImporter>());
  registry.add(std::make_unique<spira::import_mesh::PlyImporter>());
}
