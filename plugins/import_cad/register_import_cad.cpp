#include <memory>

#include "cad_importer.h"
#include "spira/plugin/plugin_registry.h"

void spira_register_import_cad(spira::PluginRegistry& registry)
{
  using spira::import_cad::CadFormat;
  using spira::import_cad::CadImporter;
  for (CadFormat f : {CadFormat::Step, CadFormat::Iges, CadFormat::Brep})
    registry.add(std::make_unique<CadImporter>(f));
}
