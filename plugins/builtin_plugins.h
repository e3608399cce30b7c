#pragma once

namespace spira {

class PluginRegistry;

// Adds every plugin linked into this program to `registry`.
void registerBuiltinPlugins(PluginRegistry& registry);

// The process-wide registry holding the built-in plugins (created on first use).
PluginRegistry& builtinRegistry();

}  // namespace spira
