#include <memory>

#include "max_min_geodesic.h"
#include "spira/plugin/plugin_registry.h"

void spira_register_closure_zone(spira::PluginRegistry& registry)
{
  registry.add(std::make_unique<spira::closure_zone::MaxMinGeodesicClosure>());
}
