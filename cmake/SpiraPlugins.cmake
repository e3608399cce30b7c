# Built-in plugins are static libraries. Each defines one registration function
#   void spira_register_<NAME>(spira::PluginRegistry&);
# spira_add_plugin() records it, and spira_generate_builtin_plugins() writes the single
# translation unit that calls them all, so no plugin relies on static-initialiser tricks
# that a static link would silently drop.
# Usage: spira_add_plugin(NAME <name> SOURCES ... [LIBRARIES ...])
function(spira_add_plugin)
  cmake_parse_arguments(P "" "NAME" "SOURCES;LIBRARIES" ${ARGN})
  if(NOT P_NAME)
    message(FATAL_ERROR "spira_add_plugin: NAME is required")
  endif()
  set(NAME ${P_NAME})
  set(target spira_plugin_${NAME})
  add_library(${target} STATIC ${P_SOURCES})
  target_link_libraries(${target} PUBLIC spira_core_all PRIVATE ${P_LIBRARIES})
  spira_target_warnings(${target})
  set_property(GLOBAL APPEND PROPERTY SPIRA_BUILTIN_PLUGINS ${NAME})
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
  target_link_libraries(spira_plugins PUBLIC spira_core_all ${targets})
endfunction()
