// `spira-cli plan PROJECT.spira -o DIR [--save]`: plans a saved project with everything it holds
// (part, placement, substrate, cell, settings) through the same pipeline as the GUI's Plan.
#include <filesystem>
#include <iostream>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/output_set.h"
#include "spira/base/progress.h"
#include "spira/document/document.h"
#include "spira/io/isolated_import.h"
#include "spira/pipeline/document_plan.h"
#include "spira/pipeline/planned_path.h"
#include "spira/planning/joints_csv.h"
#include "spira/planning/plan_files.h"

namespace fs = std::filesystem;

namespace spira::cli {
namespace {

// The plan's report.json: a part's plan folder report with where the project's part and cell came from.
nlohmann::json folderReport(const Document& doc, const fs::path& project, const DocumentPlan& plan)
{
  nlohmann::json report = plan.report;
  report["project"] = fs::absolute(project).lexically_normal().string();
  const Part& part = *doc.part();
  report["part"] = part.sourcePath.empty() ? part.name : part.sourcePath;
  if (doc.cell()) report["cell"] = doc.cell()->name;
  report["deposit_summary"] = plan.depositSummary;
  return report;
}

}  // namespace

int cmdPlanProject(Args args, const fs::path& project)
{
  const std::string outDir = args.takeOption("-o");
  const bool save = args.takeSwitch("--save");
  for (const std::string& a : args.rest)
    if (a != project.string())
      throw UsageError("'plan " + project.filename().string() + "' takes only -o DIR and --save, not '" + a +
                           "': the part, its placement, the cell and every setting are the project's",
                       "change them in Spira and save the project, or plan the part file with flags");
  if (outDir.empty()) throw UsageError("'plan' needs an output folder", "write -o DIR");
  ensureWritableDirectory(outDir);

  Document doc;
  doc.open(project);
  if (!doc.part())
    throw InputError("the project '" + project.string() + "' holds no part",
                     "import a part into it in Spira and save it");
  if (doc.cell()) prestartImportHelper();
  const DocumentState snapshot = doc.state();
  NullProgress progress;
  const DocumentPlan plan = planDocument(snapshot, builtinRegistry(), progress);

  const Results& r = plan.results;
  std::vector<OutputFile> files{{"trajectory.csv", trajectoryCsv(*plannedPathOf(r).trajectory)}};
  if (r.kinematics) files.push_back({"joints.csv", jointsCsv(r.kinematics->joints)});
  files.push_back({"report.json", folderReport(doc, project, plan).dump(2) + "\n"});
  replaceOutputSet(outDir, OutputKind::Plan, files);

  std::cout << plan.summary << "\n";
  std::cout << (plan.feasible ? "feasible" : "INFEASIBLE") << ": " << plan.depositSummary << "\n";
  if (plan.advice) std::cout << "advice: " << plan.advice->text() << "\n";
  for (const std::string& w : plan.warnings) std::cout << "warning: " << w << "\n";
  std::cout << "wrote " << outDir << "/trajectory.csv" << (r.kinematics ? ", joints.csv" : "")
            << " and report.json\n";
  if (save) {
    storePlanResults(doc, snapshot, plan.results);
    doc.save();
    std::cout << "saved the plan into " << project.string() << "\n";
  }
  return plan.feasible && plan.motionOk ? kExitOk : kExitInfeasible;
}

}  // namespace spira::cli
