#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "spira/base/output_set.h"
#include "spira/base/progress.h"
#include "spira/export/export_path.h"
#include "spira/plugin/parameter.h"

namespace spira {

// The steps every robot-program exporter takes before and after its own writer, done once here so
// the exporters differ only in what they write.

// The parameters an exporter writes with: the caller's values completed with the schema's defaults
// and validated, and the shared path settings read from them.
struct ExportStart {
  ParamSet values;
  PathOptions options;
};

// Completes and validates `params` against `schema`, checks that `outDir` can take the files
// before any work is done (IoError otherwise) and reads the shared settings for `controller`.
ExportStart startExport(const ParamSchema& schema, const ParamSet& params,
                        const std::filesystem::path& outDir, const std::string& controller);

// Writes the program's files into `outDir` as one set replacing the previous program, all of them
// or none (replaceOutputSet), reporting progress to the end; returns the written paths.
std::vector<std::filesystem::path> finishExport(const std::filesystem::path& outDir,
                                                const std::vector<OutputFile>& files, Progress& progress);

}  // namespace spira
