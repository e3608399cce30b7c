// The complete G-code program of a small plan (the golden cylinder of the robot exporters, 3
// revolutions of 8 points, its torch leant outwards), reviewed line by line when it was made. The
// Spira version in the comment block is replaced by @VERSION@ before comparing; after a deliberate
// change of the output, regenerate with SPIRA_UPDATE_GOLDEN=1 and review the diff.
#include <gtest/gtest.h>

#include <cstdlib>

#include "export/export_test_data.h"
#include "spira/base/units.h"
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

TEST(GcodeGolden, SmallCylinder)
{
  test::TempDir dir;
  Trajectory plan = test::cylinderPlan(3, 8);
  for (auto& p : plan.points) p.build = (std::cos(0.3) * p.build - std::sin(0.3) * p.normal).normalized();
  ParamSet params;
  params.set("machine", (test::sourceDir() / "resources" / "machines" / "gantry_ca_head.machine").string());
  params.set("program_name", std::string("small_cylinder"));
  params.set("line_numbers", true);
  params.set("wfs_deadband", 0.1);
  const ExportResult result = test::runExporter("export.gcode", plan, nullptr, params, dir.path());
  ASSERT_EQ(result.files.size(), 1u);
  const std::filesystem::path golden =
      test::sourceDir() / "tests" / "export" / "golden" / "small_cylinder.nc";
  const std::string got = withoutVersion(test::readBytes(result.files[0]));
  if (std::getenv("SPIRA_UPDATE_GOLDEN")) test::writeBytes(golden, got);
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden;
  const std::string want = test::readBytes(golden);
  size_t line = 1, i = 0;
  while (i < got.size() && i < want.size() && got[i] == want[i]) line += got[i++] == '\n';
  EXPECT_EQ(got, want) << "first difference at line " << line;
}

}  // namespace
}  // namespace spira
