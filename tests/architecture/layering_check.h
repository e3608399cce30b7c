#pragma once

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace spira::layering {

// The allowed arrows between the parts of the source tree, checked on every #include:
//   core area X -> core area Y   only when core/CMakeLists.txt lists spira_Y in X's DEPS, and every
//                                listed area is included somewhere in X (the lists say exactly what
//                                the code uses); the DEPS graph has no cycle.
//   core area X -> third party   only the libraries listed in X's DEPS (Eigen, nlohmann-json, TBB,
//                                CGAL, CHOLMOD, urdfdom); never Qt or VTK.
//   core -> ui, app, plugins     never.
//   ui -> plugins                never (builtin_plugins.h included: app/ passes the registry in).
//   plugin P -> plugin Q         never; a plugin reaches another one only through the registry.
//   plugin P -> core area X      only the areas of spira_sdk and those P's spira_add_plugin() lists
//                                in AREAS, and every listed area is included somewhere in P (its
//                                tests, plugins/P/tests, link all of core and are not held to it).
//   anything outside plugins/P, P's own tests included -> a header of P
//                                only the headers P's spira_add_plugin() lists in PUBLIC_HEADERS.
//   examples/plugin_sdk (its plugins, not its test) -> core area X   only the areas of spira_sdk.
// core/CMakeLists.txt is the one table of the core's arrows and plugins/*/CMakeLists.txt the
// plugins'; this check reads them.

struct Violation {
  std::string file;  // relative to the checked root
  int line = 0;      // 1-based
  std::string what;
};
std::string describe(const Violation& v);  // "file:line: what"

struct CoreArea {
  int line = 0;                     // of its spira_core_area() in core/CMakeLists.txt
  std::set<std::string> areas;      // spira_<area> names in DEPS, without the prefix
  std::set<std::string> libraries;  // the other DEPS (third-party targets)
};

// The spira_core_area(<name> DEPS ...) calls of a core/CMakeLists.txt.
std::map<std::string, CoreArea> readCoreAreas(const std::filesystem::path& cmakeLists);

// The spira_<area> names, without the prefix, that core/CMakeLists.txt links into spira_sdk.
std::set<std::string> readSdkAreas(const std::filesystem::path& cmakeLists);

struct PluginDeclaration {
  int line = 0;                         // of its spira_add_plugin() in its CMakeLists.txt
  std::set<std::string> areas;          // AREAS
  std::set<std::string> publicHeaders;  // PUBLIC_HEADERS, relative to the plugin's folder
};

// The spira_add_plugin(...) call of a plugins/<name>/CMakeLists.txt.
PluginDeclaration readPluginDeclaration(const std::filesystem::path& cmakeLists);

// Every include under root (core/spira, ui, plugins, and for plugin headers tests, bench, app,
// examples and fuzz) that crosses an arrow not allowed above.
std::vector<Violation> checkTree(const std::filesystem::path& root);

}  // namespace spira::layering
