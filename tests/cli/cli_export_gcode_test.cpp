// spira-cli with --format gcode / --export gcode: the machine file replaces the cell, and bad
// machines and missing flags give the documented exit codes.
#include <gtest/gtest.h>

#include "cli_runner.h"
#include "spira/base/exit_code.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

fs::path resource(const std::string& sub)
{
  return sourceDir() / "resources" / sub;
}

size_t count(const std::string& text, const std::string& what)
{
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(CliExportGcode, PlanAndExportWriteOneArcWithTheMachineInsteadOfTheCell)
{
  TempDir dir;
  const std::string machine = resource("machines/gantry_ca_head.machine").string();
  const CliRun r = runCli({"plan", resource("samples/open_cylinder.stl").string(), "-o", dir.path().string(),
                           "--cell", resource("cells/kuka_kr16_2_table.cell").string(), "--export", "gcode",
                           "--machine", machine, "--program-name", "wall1"});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const std::string nc = readBytes(dir / "wall1.nc");
  EXPECT_NE(nc.find("(part: open_cylinder.stl)"), std::string::npos);
  EXPECT_NE(nc.find("gantry_ca_head.machine)"), std::string::npos);
  EXPECT_EQ(count(nc, "\nM62 P0\n"), 1u);
  EXPECT_EQ(count(nc, "\nM63 P0\n"), 1u);
  EXPECT_GT(count(nc, "\nG1 "), 100u);

  // The plan folder names a KUKA cell: the G-code export does not solve it, nor name it.
  const fs::path out = dir / "nc";
  const CliRun e =
      runCli({"export", dir.path().string(), "--format", "gcode", "--machine", machine, "-o", out.string()});
  ASSERT_EQ(e.exitCode, 0) << e.err << e.out;
  const std::string again = readBytes(out / "spira_part.nc");
  EXPECT_EQ(again.find("(cell:"), std::string::npos);
  EXPECT_EQ(count(again, "\nM62 P0\n"), 1u);
}

TEST(CliExportGcode, MissingAndBadMachinesAreRefused)
{
  TempDir dir;
  const CliRun r =
      runCli({"plan", resource("samples/open_cylinder.stl").string(), "-o", dir.path().string()});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const fs::path out = dir / "nc";
  CliRun e = runCli({"export", dir.path().string(), "--format", "gcode", "-o", out.string()});
  EXPECT_EQ(e.exitCode, kExitBadInput) << e.err;
  EXPECT_NE(e.err.find("--machine"), std::string::npos) << e.err;

  writeBytes(dir / "bad.machine",
             R"({"spira_machine": 1, "linear_axes": [{"min_mm": 0, "max_mm": 1}, {"min_mm": 0, "max_mm": 1},
                 {"letter": "X", "min_mm": 0, "max_mm": 1}],
                 "rotary_axes": [{"letter": "C", "about": "Z", "min_deg": -1, "max_deg": 1},
                                 {"letter": "A", "about": "X", "min_deg": -1, "max_deg": 1}]})");
  e = runCli({"export", dir.path().string(), "--format", "gcode", "--machine", (dir / "bad.machine").string(),
              "-o", out.string()});
  EXPECT_EQ(e.exitCode, kExitBadInput) << e.err;
  EXPECT_NE(e.err.find("linear_axes[2] (Z): letter X is used by two axes"), std::string::npos) << e.err;

  e = runCli({"export", dir.path().string(), "--format", "gcode", "--machine",
              resource("machines/gantry_ca_head.machine").string(), "--decimals", "9", "-o", out.string()});
  EXPECT_EQ(e.exitCode, kExitUsage) << e.err;
  EXPECT_NE(e.err.find("'decimals' = 9 is out of range"), std::string::npos) << e.err;
  EXPECT_FALSE(fs::exists(out / "spira_part.nc"));
}

}  // namespace
}  // namespace spira::test
