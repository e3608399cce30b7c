#pragma once

#include <filesystem>
#include <string>

#include "spira/base/progress.h"
#include "spira/plugin/importer.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {

// What the import helper may use before the parent gives up on it. Defaults: the smaller of
// 4 GB and half the physical memory, 120 s of wall-clock time; the environment variables
// SPIRA_IMPORT_MEMORY_MB and SPIRA_IMPORT_TIMEOUT_S override them.
struct ImportLimits {
  size_t memoryBytes = 0;
  double wallSeconds = 0.0;
  static ImportLimits fromEnvironment();
};

// Runs `importer` on `file` in the spira-import helper process, so that a crash, an abort, a
// hang or a memory blow-up in a third-party parser becomes an InputError naming the file. The
// helper's own messages come back as warnings. Cancelling `progress` kills the helper.
ImportedMesh readIsolated(const ImporterPlugin& importer, const std::filesystem::path& file,
                          const ParamSet& params, Progress& progress);
// The same for an importer only the helper has (robot link meshes through Assimp); `reexport`
// tells the user how to get a readable file when the reader crashes or exceeds its limits.
ImportedMesh readIsolated(const std::string& importerId, const std::filesystem::path& file,
                          const ParamSet& params, Progress& progress, const std::string& reexport);

// Starts the helper's warm server in the background, so that the first import of a session does
// not wait for it to load OpenCASCADE (see import_process.h). Imports start it anyway.
void prestartImportHelper();

// The helper: next to the running executable, else the build tree's one; throws IoError when
// neither exists.
std::filesystem::path importHelperPath();

// spira-import's main: `spira-import IMPORTER_ID FILE PARAMS_JSON MEMORY_BYTES CPU_SECONDS`,
// the result on file descriptor 3, its messages (and OpenCASCADE's) on standard error; or
// `spira-import --serve`, the warm server, with its socket on file descriptor 3. It ends the
// process itself (_exit) instead of returning.
int importHelperMain(int argc, char** argv, const PluginRegistry& registry);

}  // namespace spira
