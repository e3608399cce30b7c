#include "spira/ui/jobs/export_request.h"

#include <ctime>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <QTemporaryDir>

#include "spira/base/error.h"
#include "spira/pipeline/document_plan.h"
#include "spira/pipeline/planned_path.h"
#include "spira/pipeline/prep_schema.h"
#include "spira/pipeline/program_header.h"
#include "spira/robotcell/robot_cell.h"

namespace spira::ui {

namespace {

PreviewFile readHead(const std::filesystem::path& file, size_t lines)
{
  PreviewFile f;
  f.name = file.filename().string();
  std::ifstream in(file, std::ios::binary);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // FANUC TP files end lines with CRLF
    if (f.lines.size() < lines) f.lines.push_back(line);
    ++f.totalLines;
  }
  return f;
}

}  // namespace

ExportRequest makeExportRequest(const Results& results, const std::string& partName,
                                const std::shared_ptr<const CellRecord>& cell)
{
  ExportRequest r;
  // With the kinematics stage, its path: the plan with the torch tilts that cleared collisions.
  PlannedPath planned = plannedPathOf(results);
  r.trajectory = std::move(planned.trajectory);
  r.plannedCollision = std::move(planned.collision);
  if (cell) r.cell = *cell;
  const std::optional<PlanReportSummary> plan = planSummaryOf(results);
  r.header = programHeader(partName, cell ? cell->name : std::string(), plan ? *plan : PlanReportSummary(),
                           std::time(nullptr));
  if (!plan) r.header.erase("plan");
  if (plan) r.positionerToleranceDeg = plan->positionerToleranceDeg;
  return r;
}

namespace {

ExportOutcome run(const PluginRegistry& registry, const ExportRequest& request,
                  const ParamSet& exporterParams, const std::filesystem::path& outDir, Progress& progress)
{
  if (!request.trajectory || request.trajectory->empty())
    throw InputError("there is no planned path to export", "plan the part first (Plan > Plan, F5)");
  std::optional<RobotCell> cell;
  if (request.cell) {
    cell.emplace(*request.cell);
    if (!cell->canSolve()) throw InputError(cell->ikRefusal(), "choose a cell with a 6-axis arm");
  }
  ExportJob job;
  job.exporterId = request.exporterId;
  job.exporterParams = exporterParams;
  job.prep = prepParamsFrom(request.prepParams);
  job.cell = cell ? &*cell : nullptr;
  job.header = request.header;
  job.positionerToleranceDeg = request.positionerToleranceDeg;
  if (job.cell)
    job.plannedCollision = request.plannedCollision;  // collisions need the cell they were found with
  return exportTrajectory(registry, *request.trajectory, job, outDir, progress);
}

}  // namespace

ExportPreview previewExport(const PluginRegistry& registry, const ExportRequest& request, size_t lines,
                            Progress& progress)
{
  QTemporaryDir dir;
  if (!dir.isValid())
    throw IoError("cannot make a temporary folder for the export preview: " + dir.errorString().toStdString(),
                  "check that the temporary folder (TMPDIR) is writable");
  ParamSet params = request.exporterParams;
  // A preview shows the program even where a point is flagged; the warnings say so. Formats whose
  // program has nothing to force (no reach, no collisions: a gantry's G-code) have no such setting.
  if (registry.exporter(request.exporterId).schema().find("force")) params.set("force", true);
  ExportPreview preview;
  preview.outcome = run(registry, request, params, dir.path().toStdString(), progress);
  for (const auto& file : preview.outcome.result.files) preview.files.push_back(readHead(file, lines));
  return preview;
}

ExportOutcome runExport(const PluginRegistry& registry, const ExportRequest& request,
                        const std::filesystem::path& outDir, Progress& progress)
{
  return run(registry, request, request.exporterParams, outDir, progress);
}

std::vector<std::string> exportWarnings(const Results& results, const ExportPreview* preview)
{
  std::vector<std::string> out;
  std::ostringstream s;
  if (results.process) {
    if (const std::optional<PlanWindow> window = planWindow(results)) {
      size_t outside = 0;
      for (const TrajectoryPoint& p : results.process->points) outside += window->outside(p.height);
      if (outside > 0)
        out.push_back(std::to_string(outside) +
                      " planned point(s) need a deposit height outside the process window.");
    }
  }
  // The kinematics stage, when the plan was solved on the cell.
  if (const auto& k = results.kinematics) {
    size_t unreachable = 0, collisions = 0;
    for (const KinematicsCheck& c : k->checks) unreachable += !c.reachable, collisions += c.collision;
    if (unreachable > 0)
      out.push_back(std::to_string(unreachable) +
                    " planned point(s) are out of the robot's reach or joint limits.");
    if (collisions > 0)
      out.push_back(std::to_string(collisions) + " planned point(s) put the torch in collision.");
    const double speed =
        results.reports.kinematics ? results.reports.kinematics->motion.maxJointSpeedRatio : 0.0;
    if (speed > 1.0) {
      s << std::fixed << std::setprecision(0) << "A joint would have to turn at " << 100.0 * speed
        << " % of its speed limit (" << results.reports.kinematics->motion.maxJointSpeedAxis
        << "): the robot will slow the path down.";
      out.push_back(s.str());
    }
  }
  if (preview) {
    const ExportOutcome& o = preview->outcome;
    if (o.unreachableTargets > 0)
      out.push_back(
          std::to_string(o.unreachableTargets) + " of " + std::to_string(o.robotTargets) +
          " robot targets cannot be reached: the export is refused unless \"Export anyway\" is on.");
    for (const std::string& w : o.result.warnings) out.push_back(w);
  }
  return out;
}

}  // namespace spira::ui
