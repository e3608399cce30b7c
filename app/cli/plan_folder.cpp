#include "plan_folder.h"

#include "cli_common.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/output_set.h"
#include "spira/io/json_read.h"
#include "spira/path/process_model.h"
#include "spira/planning/trajectory_csv_reader.h"

namespace fs = std::filesystem;

namespace spira::cli {

PlanFolder readPlanFolder(const fs::path& dir)
{
  if (!fs::is_directory(dir))
    throw InputError("'" + dir.string() + "' is not a plan folder", "give the -o folder of 'spira-cli plan'");
  verifyOutputSet(dir);
  PlanFolder p;
  p.trajectory = readTrajectoryCsv(dir / "trajectory.csv");
  const fs::path report = dir / "report.json";
  if (fs::exists(report)) {
    const nlohmann::json j = parsePlanReport(readFile(report), report.string());
    p.report = summarisePlanReport(j, report.string());
    p.droppedMm =
        json_read::number(j, "dropped_mm", 0.0, report.string(), "plan the part again with spira-cli plan");
    p.levelledBase = j.contains("levelled_base");
  }
  return p;
}

size_t atFlag(const std::string& text, const Trajectory& plan)
{
  if (text.empty())
    throw UsageError("--at INDEX is missing", "give the number of points deposited, e.g. --at 5000");
  const long long at = wholeNumberFlag("--at", text, 0, 1000000000000LL, "--at 5000");
  if (at < 1 || size_t(at) > plan.size())
    throw InputError("--at " + text + " is outside the plan's " + std::to_string(plan.size()) + " points",
                     "give the number of points deposited, from 1 to " + std::to_string(plan.size()));
  return size_t(at);
}

double beadWidthFlag(const std::string& text)
{
  return positiveFlag("--bead-width", text, kDefaultBeadWidth, false);
}

}  // namespace spira::cli
