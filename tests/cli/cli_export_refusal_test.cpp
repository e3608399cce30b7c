// An export refused because the cell cannot execute some points (unreachable, colliding,
// outside the joint limits) is an infeasible plan, exit 4, not bad input (3): the plan and the
// files are fine, the cell is not up to them.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cell_variant.h"
#include "cli_runner.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

std::string slurp(const fs::path& p)
{
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

nlohmann::json readReport(const fs::path& dir)
{
  return nlohmann::json::parse(slurp(dir / "report.json"));
}

// The KUKA cell with the part 1.5 m beyond its reach.
fs::path outOfReachCell(const fs::path& dir)
{
  return bundledCellVariant("kuka_kr16_2_table.cell", dir, [](nlohmann::json& c) {
    c["part"]["pose"]["xyz_mm"] = {3500, 0, 400};
  });
}

TEST(CliExportRefusal, UnreachablePointsMakeTheExportInfeasible)
{
  TempDir dir;
  const fs::path cell = outOfReachCell(dir.path());
  const fs::path plan = dir / "plan";
  const CliRun planned = runCli({"plan", cylinderPart(dir.path(), 50.0, 30.0).string(), "-o", plan.string(),
                                 "--cell", cell.string(), "--points-per-rev", "36", "--export", "krl"});
  EXPECT_EQ(planned.exitCode, 4) << planned.err << planned.out;
  EXPECT_NE(planned.err.find("unreachable"), std::string::npos) << planned.err;
  EXPECT_EQ(readReport(plan)["reachable"], false);

  const fs::path program = dir / "program";
  const CliRun exported = runCli({"export", plan.string(), "--format", "krl", "-o", program.string()});
  EXPECT_EQ(exported.exitCode, 4) << exported.err << exported.out;
  EXPECT_NE(exported.err.find("cannot be executed as planned"), std::string::npos) << exported.err;
  EXPECT_TRUE(!fs::exists(program) || fs::is_empty(program));
  // Forced, the same export is written.
  const CliRun forced =
      runCli({"export", plan.string(), "--format", "krl", "-o", program.string(), "--force"});
  EXPECT_EQ(forced.exitCode, 0) << forced.err << forced.out;
}

}  // namespace
}  // namespace spira::test
