// Golden files: the complete programs for a small cylinder plan (3 revolutions of 8 points, a
// solved cell with a positioner, wire feed on an analog output), reviewed line by line when they
// were made. The Spira version in the comment block is replaced by @VERSION@ before comparing.
// After a deliberate change of the output, regenerate with SPIRA_UPDATE_GOLDEN=1 and review the
// diff before committing it.
#include <gtest/gtest.h>

#include <cstdlib>

#include "export_test_data.h"
#include "spira/base/version.h"
#include "support/test_support.h"

namespace spira {
namespace {

std::string withoutVersion(std::string text)
{
  const std::string version = kVersion;
  for (size_t at = text.find(version); at != std::string::npos; at = text.find(version, at))
    text.replace(at, version.size(), "@VERSION@");
  return text;
}

void expectGolden(const std::filesystem::path& produced)
{
  const std::filesystem::path golden =
      test::sourceDir() / "tests" / "export" / "golden" / produced.filename();
  const std::string got = withoutVersion(test::readBytes(produced));
  if (std::getenv("SPIRA_UPDATE_GOLDEN")) test::writeBytes(golden, got);
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden;
  const std::string want = test::readBytes(golden);
  if (got == want) return;
  // Point at the first differing line instead of dumping both files.
  size_t line = 1, i = 0;
  while (i < got.size() && i < want.size() && got[i] == want[i]) line += got[i++] == '\n';
  const auto lineAt = [](const std::string& s, size_t pos) {
    const size_t b = s.rfind('\n', pos == 0 ? 0 : pos - 1);
    const size_t start = b == std::string::npos ? 0 : b + 1;
    return s.substr(start, s.find('\n', start) - start);
  };
  ADD_FAILURE() << produced.filename() << " differs from its golden file at line " << line
                << ":\n  got:  " << lineAt(got, i) << "\n  want: " << lineAt(want, i);
}

TEST(ExportGolden, KrlSmallCylinder)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(3, 8);
  const JointTrajectory joints = test::syntheticJoints(plan, "kuka_krc4", true);
  ParamSet params;
  params.set("program_name", std::string("small_cylinder"));
  params.set("process_command", std::string("speed_analog"));
  params.set("job_output", std::int64_t{17});
  params.set("weld_job", std::int64_t{5});
  params.set("end_job", std::int64_t{6});
  params.set("wfs_deadband", 0.1);
  const ExportResult result = test::runExporter("export.krl", plan, &joints, params, dir.path());
  ASSERT_EQ(result.files.size(), 2u);
  for (const auto& f : result.files) expectGolden(f);
}

TEST(ExportGolden, FanucTpSmallCylinder)
{
  test::TempDir dir;
  const Trajectory plan = test::cylinderPlan(3, 8);
  const JointTrajectory joints = test::syntheticJoints(plan, "fanuc_r30ib", true);
  ParamSet params;
  params.set("program_name", std::string("small_cylinder"));
  params.set("process_command", std::string("speed_analog"));
  params.set("wfs_gain", 1000.0);
  params.set("wfs_deadband", 0.1);
  params.set("weld_schedule", std::int64_t{3});
  params.set("end_schedule", std::int64_t{4});
  const ExportResult result = test::runExporter("export.fanuc_tp", plan, &joints, params, dir.path());
  ASSERT_EQ(result.files.size(), 1u);
  expectGolden(result.files[0]);
}

}  // namespace
}  // namespace spira
