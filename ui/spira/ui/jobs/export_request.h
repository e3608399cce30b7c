#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "spira/document/kinematics_result.h"
#include "spira/document/results.h"
#include "spira/pipeline/export_job.h"
#include "spira/plugin/parameter.h"
#include "spira/robotcell/cell_record.h"

namespace spira {
class PluginRegistry;
class Progress;
}  // namespace spira

namespace spira::ui {

// Everything a robot-program export needs, copied from the document on the GUI thread so that a
// worker can run it without touching the document.
struct ExportRequest {
  std::shared_ptr<const Trajectory> trajectory;  // plannedPathOf(): the path the robot follows
  std::vector<bool> plannedCollision;            // per point: the plan left it in collision
  std::optional<CellRecord> cell;                // none: targets are torch poses in the part frame
  std::string exporterId;
  ParamSet exporterParams;
  ParamSet prepParams;  // the "prep" schema (prep_schema.h)
  std::map<std::string, std::string> header;
  std::optional<double> positionerToleranceDeg;  // the plan's (ExportJob)
};

// The request for `results` of a document with this part name and cell; the header names the
// part, the cell, the date and the plan's key figures as the CLI's does.
ExportRequest makeExportRequest(const Results& results, const std::string& partName,
                                const std::shared_ptr<const CellRecord>& cell);

// The first lines of one file an export would write.
struct PreviewFile {
  std::string name;
  std::vector<std::string> lines;
  size_t totalLines = 0;
};

struct ExportPreview {
  std::vector<PreviewFile> files;
  ExportOutcome outcome;
};

// Runs the export into a temporary folder (removed afterwards) with the exporter's `force` set, so
// that a plan the exporter would refuse still shows what it would write; keeps `lines` lines of
// each file. Worker thread: touches nothing but the request.
ExportPreview previewExport(const PluginRegistry& registry, const ExportRequest& request, size_t lines,
                            Progress& progress);

// Writes the program into `outDir` (all files or none). Throws what exportTrajectory() throws.
ExportOutcome runExport(const PluginRegistry& registry, const ExportRequest& request,
                        const std::filesystem::path& outDir, Progress& progress);

// What the user should know before writing: points outside the process window, unreachable or
// colliding points and joint-speed ratios from the plan's reports, and what the preview found.
std::vector<std::string> exportWarnings(const Results& results, const ExportPreview* preview);

}  // namespace spira::ui
