# Built-in plugins are static libraries. Each defines one registration function
#   void spira_register_<NAME>(spira::PluginRegistry&);
# spira_add_plugin() records it, and spira_generate_builtin_plugins() writes the single
# translation unit that calls them all, so no plugin relies on static-initialiser tricks
# that a static link would silently drop.
# Usage:
#   spira_add_plugin(NAME <name> SOURCES ... [AREAS <core area> ...] [LIBRARIES ...]
#                    [PUBLIC_HEADERS <header> ...])
# A plugin links spira_sdk (core/CMakeLists.txt) and, by name, the further core areas its files
# include (AREAS: "field", "export", ...); LIBRARIES are third-party targets. PUBLIC_HEADERS are
# the plugin's headers that code outside its folder, its own tests included, may include as
# "<name>/<header>"; the rest are its internals. tests/architecture checks both lists against the
# includes. The plugin's tests (plugins/<name>/tests/*.cpp) become test_<name> (tests/CMakeLists.txt).
function(spira_add_plugin)
  cmake_parse_arguments(P "" "NAME" "SOURCES;AREAS;LIBRARIES;PUBLIC_HEADERS" ${ARGN})
  if(NOT P_NAME)
    message(FATAL_ERROR "spira_add_plugin: NAME is required")
  endif()
  set(NAME ${P_NAME})
  set(target spira_plugin_${NAME})
  foreach(header IN LISTS P_PUBLIC_HEADERS)
    if(NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${header})
      message(FATAL_ERROR "spira_add_plugin(${NAME}): public header ${header} does not exist")
    endif()
  endforeach()
  list(TRANSFORM P_AREAS PREPEND spira_ OUTPUT_VARIABLE areas)
  add_library(${target} STATIC ${P_SOURCES})
  # The areas are public: the public headers may include them, and a static link must list them
  # after the plugin.
  target_link_libraries(${target} PUBLIC spira_sdk ${areas} PRIVATE ${P_LIBRARIES})
  spira_target_warnings(${target})
  set_property(GLOBAL APPEND PROPERTY SPIRA_BUILTIN_PLUGINS ${NAME})
  set_property(GLOBAL PROPERTY SPIRA_PLUGIN_DIR_${NAME} ${CMAKE_CURRENT_SOURCE_DIR})
endfunction()

function(spira_generate_builtin_plugins)
  get_property(names GLOBAL PROPERTY SPIRA_BUILTIN_PLUGINS)
  set(decls "")
  set(calls "")
  set(targets "")
  foreach(n IN LISTS names)
    string(APPEND decls "void spira_register_${n}(spira::PluginRegistry&);\n")
    string(APPEND calls "  spira_register_${n}(registry);\n")
    list(APPEND targets spira_plugin_${n})
  endforeach()
  configure_file(${PROJECT_SOURCE_DIR}/cmake/builtin_plugins.cpp.in ${CMAKE_CURRENT_BINARY_DIR}/builtin_plugins.cpp @ONLY)
  add_library(spira_plugins STATIC ${CMAKE_CURRENT_BINARY_DIR}/builtin_plugins.cpp)
  target_include_directories(spira_plugins PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(spira_plugins PUBLIC spira_sdk ${targets})
endfunction()
