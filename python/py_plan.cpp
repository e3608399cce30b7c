#include "py_plan.h"

#include <cstdlib>
#include <ctime>
#include <filesystem>

#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include "builtin_plugins.h"
#include "py_arrays.h"
#include "py_errors.h"
#include "py_json.h"
#include "py_options.h"
#include "py_part.h"
#include "py_progress.h"
#include "spira/base/error.h"
#include "spira/document/document.h"
#include "spira/document/project_file.h"
#include "spira/pipeline/document_motion.h"
#include "spira/pipeline/export_job.h"
#include "spira/pipeline/planned_path.h"
#include "spira/pipeline/prep_schema.h"
#include "spira/pipeline/program_header.h"
#include "spira/pipeline/thermal_schema.h"
#include "spira/planning/settings_sections.h"
#include "spira/plugin/strategy_name.h"
#include "spira/robotcell/cell_file.h"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace spira::python {
namespace {

LoadedCell readCell(const std::string& path)
{
  LoadedCell out;
  out.path = path;
  out.record = std::make_shared<const CellRecord>(readCellFile(path));
  out.cell = std::make_shared<const RobotCell>(*out.record);
  if (!out.cell->canSolve()) throw InputError(out.cell->ikRefusal(), "choose a cell with a 6-axis arm");
  return out;
}

// The plan's settings targets, as the CLI's PlanFlags and the thermal section the pipeline reads.
struct PlanTargets {
  std::map<std::string, ParamSet> values;
  std::vector<FlagTarget> targets;
  PlanTargets()
  {
    const PluginRegistry& registry = builtinRegistry();
    std::vector<std::pair<std::string, const ParamSchema*>> owners;
    for (const SettingsSection& s : planSections()) owners.emplace_back(std::string(s.name), &s.schema);
    owners.emplace_back(std::string(thermalSection().name), &thermalSection().schema);
    for (const Plugin* p : registry.ofKind(PluginKind::Decomposer))
      owners.emplace_back(p->id(), &p->schema());
    for (const Plugin* p : registry.ofKind(PluginKind::ClosureFinder))
      owners.emplace_back(p->id(), &p->schema());
    for (const auto& [owner, schema] : owners) values[owner];
    for (const auto& [owner, schema] : owners) targets.push_back(FlagTarget{owner, schema, &values[owner]});
  }
  PlanTargets(const PlanTargets&) = delete;
  PlanTargets& operator=(const PlanTargets&) = delete;
};

PlannedPart planPart(const LoadedPart& part, std::map<std::string, ParamSet> values,
                     const std::string& strategy, std::optional<LoadedCell> cell,
                     const PlanDocumentOptions& options, PythonProgress& progress)
{
  PlannedPart out;
  out.partPath = part.part->sourcePath;
  out.cell = std::move(cell);
  DocumentState& snapshot = out.snapshot;
  snapshot.part = part.part;
  if (out.cell) snapshot.cell = out.cell->record;
  Substrate plate;
  plate.planeZ = part.placement.substrateZ;
  snapshot.substrate = std::make_shared<const Substrate>(std::move(plate));
  snapshot.settings = std::make_shared<const PlanSettings>(
      PlanSettings{decomposerIdOf(strategy), PlanSettings::kDefaultClosureFinder, std::move(values)});

  out.plan = std::make_shared<DocumentPlan>(
      progress.run([&] { return planDocument(snapshot, builtinRegistry(), progress, options); }));
  nlohmann::json& report = out.plan->report;
  report["dropped_mm"] = part.placed.dropped;
  if (part.placed.levelled)
    report["levelled_base"] = {{"cut_z_mm", part.placed.cutZ}, {"removed_mm", part.placed.removed}};
  report["timings_s"]["import"] = part.importSeconds;
  if (out.cell) report["cell_file"] = fs::absolute(out.cell->path).lexically_normal().string();
  const PlannedPath planned = plannedPathOf(out.plan->results);
  out.path = planned.trajectory;
  out.collision = planned.collision;
  return out;
}

// 'spira-cli plan PROJECT.spira': the project's part, placement, cell and settings, no other choice.
PlannedPart planProject(const std::string& file, Options& options)
{
  PythonProgress progress("plan", options.take("progress"));
  for (const char* name : {"settings", "strategy", "cell"})
    if (options.has(name))
      throw UsageError(
          std::string("plan(): a project is planned with everything it holds, not with '") + name + "'",
          "change it in Spira and save the project, or plan the part file with keywords");
  options.finish();
  Document doc;
  progress.run([&] { doc.open(file); });
  if (!doc.part())
    throw InputError("the project '" + file + "' holds no part",
                     "import a part into it in Spira and save it");
  PlannedPart out;
  const Part& part = *doc.part();
  out.partPath = part.sourcePath.empty() ? part.name : part.sourcePath;
  out.snapshot = doc.state();
  if (doc.cell()) {
    LoadedCell cell{doc.cell()->name, doc.cell(), nullptr};
    // The program's targets stand in the world frame the project placed the part in.
    cell.cell = std::make_shared<const RobotCell>(cellForPlacement(*doc.cell(), part.T_world_part));
    out.cell = std::move(cell);
  }
  out.plan = std::make_shared<DocumentPlan>(
      progress.run([&] { return planDocument(out.snapshot, builtinRegistry(), progress); }));
  nlohmann::json& report = out.plan->report;
  report["project"] = fs::absolute(file).lexically_normal().string();
  report["part"] = out.partPath;
  if (doc.cell()) report["cell"] = doc.cell()->name;
  report["deposit_summary"] = out.plan->depositSummary;
  const PlannedPath planned = plannedPathOf(out.plan->results);
  out.path = planned.trajectory;
  out.collision = planned.collision;
  return out;
}

PlannedPart planFromPython(py::object part, const py::kwargs& kwargs)
{
  Options options("plan", kwargs);
  const bool fromFile = !py::isinstance<LoadedPart>(part);
  std::string file;
  if (fromFile) {
    if (!py::isinstance<py::str>(part) && !py::hasattr(part, "__fspath__"))
      raiseTypeError("plan", "part", "a spira.Part or a path (str or os.PathLike)", part);
    file = pathArgument("plan", "part", part);
    if (fs::path(file).extension() == kProjectExtension) return planProject(file, options);
  }
  ImportChoices choices;
  if (fromFile) choices.takePlacement(options);
  const std::string strategy = options.takeText("strategy").value_or(strategyName(kDefaultDecomposerId));
  std::optional<LoadedCell> cell;
  const py::object cellArg = options.take("cell");
  if (py::isinstance<LoadedCell>(cellArg))
    cell = cellArg.cast<LoadedCell>();
  else if (!cellArg.is_none())
    cell = readCell(pathArgument("plan", "cell", cellArg));
  PlanDocumentOptions planOptions;
  planOptions.midSurfaceOfSolid = options.takeBool("mid_surface").value_or(true);
  planOptions.resolveCollisions = !options.takeBool("keep_collisions").value_or(false);
  PlanTargets plan;
  std::vector<FlagTarget> targets = plan.targets;
  if (fromFile) targets.insert(targets.end(), choices.targets.begin(), choices.targets.end());
  options.takeSettings(targets);
  PythonProgress progress("plan", options.take("progress"));
  options.finish();

  const LoadedPart loaded = fromFile ? loadPart(file, choices, progress) : part.cast<LoadedPart>();
  return planPart(loaded, plan.values, strategy, std::move(cell), planOptions, progress);
}

// Plan.solve: the plan's motion on another cell (or its first), the path planned once.
PlannedPart solvePlan(const PlannedPart& planned, py::object cellArg, const py::kwargs& kwargs)
{
  Options options("solve", kwargs);
  const bool resolveCollisions = !options.takeBool("keep_collisions").value_or(false);
  PythonProgress progress("solve", options.take("progress"));
  options.finish();
  LoadedCell cell = py::isinstance<LoadedCell>(cellArg) ? cellArg.cast<LoadedCell>()
                                                        : readCell(pathArgument("solve", "cell", cellArg));
  PlannedPart out;
  out.partPath = planned.partPath;
  out.snapshot = planned.snapshot;
  out.snapshot.cell = cell.record;
  const Transform& placement = out.snapshot.part->T_world_part;
  // The program's targets stand in the world frame a project placed the part in (as planProject's).
  if (!placement.isApprox(Transform::Identity()))
    cell.cell = std::make_shared<const RobotCell>(cellForPlacement(*cell.record, placement));
  out.cell = std::move(cell);
  out.plan = std::make_shared<DocumentPlan>(*planned.plan);
  DocumentPlan& plan = *out.plan;
  Results& r = plan.results;
  const Trajectory& path = r.thermal && r.thermal->replanned ? *r.thermal->replanned : *r.process;
  // As planDocument hands the motion stage the substrate: its height in the part's frame.
  const double substrateZ =
      out.snapshot.substrate->planeZ - out.snapshot.part->T_world_part.translation().z();
  DocumentMotion motion = progress.run(
      [&] { return solveDocumentMotion(out.snapshot, path, substrateZ, progress, resolveCollisions); });
  plan.warnings = plan.output.warnings;  // a motion solved before warned of another cell
  plan.warnings.insert(plan.warnings.end(), motion.warnings.begin(), motion.warnings.end());
  plan.motionOk = motion.ok;
  r.setKinematics(std::move(motion.result), motion.report
                                                ? std::make_shared<const KinematicsStageReport>(
                                                      KinematicsStageReport{*motion.report, motion.seconds})
                                                : nullptr);
  // The stages' report with this motion, and what was added to the plan's beyond its stages (the
  // placement, the advice, the import time) kept; a cell named before is the other cell.
  const nlohmann::json stagesBefore = mergedPlanReport(planned.plan->results);
  nlohmann::json report = mergedPlanReport(r);
  for (const auto& [key, value] : planned.plan->report.items())
    if (!stagesBefore.contains(key) && key != "cell_file" && key != "cell") report[key] = value;
  for (const auto& [key, value] : planned.plan->report["timings_s"].items())
    if (!stagesBefore["timings_s"].contains(key)) report["timings_s"][key] = value;
  report["cell_file"] = fs::absolute(out.cell->path).lexically_normal().string();
  if (report.contains("project")) report["cell"] = out.cell->record->name;
  plan.report = std::move(report);
  const PlannedPath solved = plannedPathOf(r);
  out.path = solved.trajectory;
  out.collision = solved.collision;
  return out;
}

py::dict exportPlan(const PlannedPart& planned, py::object folder, py::object format,
                    const py::kwargs& kwargs)
{
  const PluginRegistry& registry = builtinRegistry();
  const std::string outDir = pathArgument("export", "folder", folder);
  if (!py::isinstance<py::str>(format)) raiseTypeError("export", "format", "str", format);
  const std::string formatName = format.cast<std::string>();
  const ExporterPlugin* found = exporterForFormat(registry, formatName);
  if (!found)
    throw UsageError("unknown program format '" + formatName + "'",
                     "use one of: " + exporterFormatList(registry));
  const ExporterPlugin& exporter = *found;
  Options options("export", kwargs);
  // A project's stored exporter and preparation values, then the keywords over them (as 'spira-cli
  // export PROJECT' merges its flags).
  const PlanSettings& stored = *planned.snapshot.settings;
  ParamSet exporterValues = stored.section(exporter.id());
  ParamSet prepValues = stored.section(std::string(prepSection().name));
  options.takeSettings({FlagTarget{exporter.id(), &exporter.schema(), &exporterValues},
                        FlagTarget{std::string(prepSection().name), &prepSchema(), &prepValues}});
  PythonProgress progress("export", options.take("progress"));
  options.finish();

  const bool forced = exporterValues.has("force") && exporterValues.getBool("force");
  if (!planned.plan->feasible && !forced)
    throw InfeasibleError(
        "the robot program was not written: the deposit check rejects the path",
        "pass force=True to write it anyway, each rejected point then carries a warning comment");
  ExportJob job;
  job.exporterId = exporter.id();
  job.exporterParams = exporterValues;
  job.prep = prepParamsFrom(prepValues);
  job.cell = planned.cell ? planned.cell->cell.get() : nullptr;
  job.plannedCollision = planned.collision;
  const PlanReportSummary summary = planSummaryOf(planned.plan->results).value_or(PlanReportSummary{});
  job.header =
      programHeader(fs::path(planned.partPath).filename().string(),
                    planned.cell ? (summary.cell.empty() ? planned.cell->path : summary.cell) : std::string(),
                    summary, programTime());
  job.positionerToleranceDeg = summary.positionerToleranceDeg;
  fs::create_directories(outDir);
  const ExportOutcome done =
      progress.run([&] { return exportTrajectory(registry, *planned.path, job, outDir, progress); });
  py::list files;
  for (const fs::path& f : done.result.files) files.append(f.string());
  py::dict out;
  out["files"] = files;
  out["warnings"] = done.result.warnings;
  out["robot_targets"] = done.robotTargets;
  out["unreachable_targets"] = done.unreachableTargets;
  out["sub_paths"] = done.subPaths;
  out["seconds"] = done.seconds;
  return out;
}

}  // namespace

void bindPlan(py::module_& m)
{
  py::class_<LoadedCell>(m, "Cell", "A robot cell (.cell file): robot, tool and positioner.")
      .def_property_readonly("path", [](const LoadedCell& c) { return c.path; })
      .def_property_readonly("name", [](const LoadedCell& c) { return c.record->name; })
      .def("__repr__", [](const LoadedCell& c) { return "<spira.Cell '" + c.record->name + "'>"; });
  m.def(
      "read_cell", [](py::object path) { return readCell(pathArgument("read_cell", "path", path)); },
      py::arg("path"),
      "read_cell(path) -> Cell\n\nReads a .cell file and checks that its robot can be solved.");

  py::class_<PlannedPart> plan(m, "Plan",
                               "A planned part: the path as numpy arrays, the report, the joints.");
  bindTrajectoryArrays(plan);
  plan.def_property_readonly(
          "report", [](const PlannedPart& p) { return toPython(p.plan->report); },
          "The plan's report, the same JSON as report.json.")
      .def_property_readonly("feasible", [](const PlannedPart& p) { return p.plan->feasible; })
      .def_property_readonly("motion_ok", [](const PlannedPart& p) { return p.plan->motionOk; })
      .def_property_readonly("warnings", [](const PlannedPart& p) { return p.plan->warnings; })
      .def_property_readonly("summary", [](const PlannedPart& p) { return p.plan->summary; })
      .def_property_readonly("advice",
                             [](const PlannedPart& p) -> py::object {
                               if (!p.plan->advice) return py::none();
                               return py::str(p.plan->advice->text());
                             })
      .def_property_readonly("cell", [](const PlannedPart& p) -> py::object {
        if (!p.cell) return py::none();
        return py::cast(*p.cell);
      });
  bindMotionArrays(plan);
  plan.def(
      "solve", &solvePlan, py::arg("cell"),
      "solve(cell, *, keep_collisions=False, progress=None) -> Plan\n\n"
      "The plan's robot motion on cell (a spira.Cell or a .cell path), the path not planned again: the\n"
      "torch checked against the deposit and substrate, the joints solved (Plan.joints), as plan(cell=).");
  plan.def(
      "export", &exportPlan, py::arg("folder"), py::arg("format"),
      "export(folder, format, *, progress=None, **settings) -> dict\n\n"
      "Writes the robot program into folder as 'spira-cli plan --export FORMAT' does: format an exporter id\n"
      "('export.krl') or its name ('krl'); settings the exporter's and the path preparation's by key\n"
      "(force=True writes an infeasible plan). Returns the files written and the target counts.");

  m.def("plan", &planFromPython, py::arg("part"),
        "plan(part, *, strategy='isovalue', cell=None, mid_surface=True, keep_collisions=False,\n"
        "     progress=None, settings=None, **settings) -> Plan\n\n"
        "Plans one continuous spiral on part as 'spira-cli plan' does: a spira.Part, a part file (with\n"
        "load_part's options) or a project (.spira, planned with everything it holds). Settings by key\n"
        "(h=2.0, points_per_rev=360, ...) or settings={section or plugin id: {key: value}};\n"
        "settings={'thermal': {'enabled': True}} runs the thermal stage. cell (a spira.Cell or a .cell\n"
        "path) solves the robot's joints. progress(fraction, stage) may return False or raise to cancel:\n"
        "spira.Cancelled is raised.");
}

}  // namespace spira::python
