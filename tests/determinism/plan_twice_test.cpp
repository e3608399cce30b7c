// The same part planned twice in one process gives the same plan to the bit: every strategy that
// accepts a part, the scalar field, the generatrices, the trajectory with all its channels, the
// report (measured times left out) and the robot program written from the plan.
#include <gtest/gtest.h>

#include <optional>

#include <nlohmann/json.hpp>

#include "builtin_plugins.h"
#include "determinism_parts.h"
#include "exact_diff.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/io/import_service.h"
#include "spira/pipeline/export_job.h"
#include "spira/pipeline/plan_records.h"
#include "spira/planning/plan_files.h"
#include "spira/planning/planner.h"
#include "spira/plugin/plugin_registry.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

struct Case {
  DeterminismPart part;
  std::string decomposer;  // plugin id
  ParamSet params;         // its parameters (unset: defaults)
  std::string name;        // of the settings, for the test's name
};

void PrintTo(const Case& c, std::ostream* out)
{
  *out << c.part.file << " with " << c.name;
}

// Every decomposer with its defaults, and the envelope projection towards the skeleton itself: with
// its defaults it projects an upright part of revolution towards the vertical line through the
// base, and the skeleton, computed all the same, only confirms that choice.
std::vector<Case> cases()
{
  ParamSet towardsSkeleton;
  towardsSkeleton.set("axis", std::string("skeleton"));
  std::vector<Case> out;
  for (const DeterminismPart& part : determinismParts()) {
    for (const Plugin* d : builtinRegistry().ofKind(PluginKind::Decomposer))
      out.push_back({part, d->id(), ParamSet(), d->id().substr(d->id().find('.') + 1)});
    out.push_back({part, "decomposer.envelope_projection", towardsSkeleton, "envelope_projection_skeleton"});
  }
  return out;
}

// One plan as the CLI makes it with default settings, or the message it was refused with.
struct Planned {
  std::optional<PlanOutput> plan;
  std::string refusal;
};

Planned plan(const ImportedPart& part, const Case& c)
{
  PlanRequest request(part.mesh, part.report);
  request.decomposerId = c.decomposer;
  request.params[c.decomposer] = c.params;
  NullProgress progress;
  Planned out;
  try {
    out.plan = planPart(builtinRegistry(), request, progress);
  } catch (const InputError& e) {
    out.refusal = e.fullMessage();
  }
  return out;
}

nlohmann::json reportWithoutTimes(const PlanOutput& plan, const std::string& strategy)
{
  nlohmann::json report = planReportJson(plan, strategy);
  report.erase("timings_s");
  return report;
}

void exportKrl(const Trajectory& trajectory, const std::filesystem::path& dir)
{
  ExportJob job;
  job.exporterId = "export.krl";
  job.header = {{"part", "determinism"}, {"date", "2024-01-01 00:00 UTC"}};
  NullProgress progress;
  exportTrajectory(builtinRegistry(), trajectory, job, dir, progress);
}

class PlanTwice : public ::testing::TestWithParam<Case> {};

TEST_P(PlanTwice, GivesTheSamePlanAndProgramToTheBit)
{
  const Case& c = GetParam();
  NullProgress progress;
  const ImportedPart part = importPart(builtinRegistry(), sourceDir() / c.part.file, nullptr, progress);
  const Planned first = plan(part, c);
  const Planned second = plan(part, c);
  ASSERT_EQ(first.plan.has_value(), second.plan.has_value()) << first.refusal << second.refusal;
  if (!first.plan) {
    // A strategy that refuses the part must refuse it the same way every time.
    EXPECT_FALSE(first.refusal.empty());
    EXPECT_EQ(first.refusal, second.refusal);
    return;
  }
  const PlanOutput& a = *first.plan;
  const PlanOutput& b = *second.plan;
  EXPECT_EQ(fieldDifference(a.field, b.field), "");
  EXPECT_EQ(generatricesDifference(a.generatrices, b.generatrices), "");
  ASSERT_EQ(trajectoryDifference(a.spiral.trajectory, b.spiral.trajectory), "");
  const nlohmann::json ra = reportWithoutTimes(a, c.decomposer), rb = reportWithoutTimes(b, c.decomposer);
  EXPECT_TRUE(ra == rb) << nlohmann::json::diff(ra, rb).dump();

  TempDir dirA, dirB;
  exportKrl(a.spiral.trajectory, dirA.path());
  exportKrl(b.spiral.trajectory, dirB.path());
  EXPECT_EQ(folderDifference(dirA.path(), dirB.path()), "");
}

std::string caseName(const ::testing::TestParamInfo<Case>& param)
{
  return partName(param.param.part) + "_" + param.param.name;
}

INSTANTIATE_TEST_SUITE_P(Parts, PlanTwice, ::testing::ValuesIn(cases()), caseName);

}  // namespace
}  // namespace spira::test
