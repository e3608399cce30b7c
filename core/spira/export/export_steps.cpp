#include "spira/export/export_steps.h"

#include "spira/base/atomic_file.h"
#include "spira/export/export_params.h"

namespace spira {

ExportStart startExport(const ParamSchema& schema, const ParamSet& params,
                        const std::filesystem::path& outDir, const std::string& controller)
{
  ExportStart start{params.withDefaults(schema), {}};
  schema.validate(start.values);
  ensureWritableDirectory(outDir);
  start.options = readPathOptions(start.values, schema, controller);
  return start;
}

std::vector<std::filesystem::path> finishExport(const std::filesystem::path& outDir,
                                                const std::vector<OutputFile>& files, Progress& progress)
{
  progress.report(0.9, "writing files");
  std::vector<std::filesystem::path> written = replaceOutputSet(outDir, OutputKind::Program, files);
  progress.report(1.0, "done");
  return written;
}

}  // namespace spira
