// The ABB chain through the real spira-cli: plan on the bundled IRB 1600 cell with --export rapid,
// then `export PLAN_DIR --format rapid` of the same folder.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "cli_runner.h"
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

// The cfx of every robtarget, and the number of robtargets.
std::set<int> cfxValues(const std::string& mod, size_t& targets)
{
  static const std::regex re(R"(CONST robtarget p\d+ := \[\[[^\]]*\],\[[^\]]*\],\[-?\d+,-?\d+,-?\d+,(\d)\])");
  std::set<int> out;
  targets = 0;
  for (auto it = std::sregex_iterator(mod.begin(), mod.end(), re); it != std::sregex_iterator(); ++it) {
    out.insert(std::stoi((*it)[1].str()));
    ++targets;
  }
  return out;
}

TEST(CliRapidExport, CylinderOnTheAbbCellGivesOneArcInOneConfiguration)
{
  TempDir dir;
  const CliRun r = runCli({"plan", resource("samples/open_cylinder.stl").string(), "-o", dir.path().string(),
                           "--cell", resource("cells/abb_irb1600_positioner.cell").string(),
                           "--points-per-rev", "120", "--export", "rapid", "--program-name", "wall1"});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const std::string mod = readBytes(dir / "wall1.mod");
  ASSERT_FALSE(mod.empty());
  EXPECT_EQ(mod.rfind("MODULE wall1\r\n", 0), 0u);
  EXPECT_NE(mod.find("! cell: ABB IRB 1600-8/1.45 with a 2-axis tilt-rotate positioner"), std::string::npos);
  EXPECT_EQ(count(mod, "    ArcLStart "), 1u);
  EXPECT_EQ(count(mod, "    ArcLEnd "), 1u);
  size_t targets = 0;
  EXPECT_EQ(cfxValues(mod, targets).size(), 1u);     // one configuration along the path
  EXPECT_EQ(targets, count(mod, "    ArcL p") + 2);  // + the strike and the end point
  // The cell's torch: 350 mm along tool0's Z.
  EXPECT_NE(mod.find("PERS tooldata tSpiraTorch := [TRUE,[[0.000,0.000,350.000],[1.00000000,"),
            std::string::npos);

  const fs::path again = dir / "again";
  const CliRun e = runCli(
      {"export", dir.path().string(), "--format", "rapid", "-o", again.string(), "--program-name", "wall1"});
  ASSERT_EQ(e.exitCode, 0) << e.err << e.out;
  // The same program; only the header's part line names the plan folder instead of the part file.
  const std::string exported = readBytes(again / "wall1.mod");
  const std::string data = "  PERS tooldata";
  ASSERT_NE(exported.find(data), std::string::npos);
  EXPECT_EQ(exported.substr(exported.find(data)), mod.substr(mod.find(data)));
}

}  // namespace
}  // namespace spira::test
