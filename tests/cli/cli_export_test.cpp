#include <gtest/gtest.h>

#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "program_text.h"
#include "spira/base/output_set.h"
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

// The whole chain on the KUKA table cell: plan, solve, prepare and write KRL; then the FANUC program
// of the same plan folder with `export`.
TEST(CliExport, CylinderOnTheKukaCellGivesOneArcOnAndOneArcOff)
{
  TempDir dir;
  const CliRun r = runCli({"plan", resource("samples/open_cylinder.stl").string(), "-o", dir.path().string(),
                           "--cell", resource("cells/kuka_kr16_2_table.cell").string(), "--points-per-rev",
                           "120", "--export", "krl", "--program-name", "wall1"});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const std::string src = readBytes(dir / "wall1.src");
  const std::string dat = readBytes(dir / "wall1.dat");
  ASSERT_FALSE(src.empty());
  EXPECT_NE(src.find("DEF wall1( )"), std::string::npos);
  EXPECT_NE(src.find("; part: open_cylinder.stl"), std::string::npos);
  EXPECT_NE(src.find("; cell: KUKA KR 16-2 on a fixed table"), std::string::npos);
  EXPECT_EQ(count(src, "$OUT[1]=TRUE"), 1u);
  EXPECT_EQ(count(src, "$OUT[1]=FALSE"), 1u);
  EXPECT_NE(dat.find("DEFDAT wall1"), std::string::npos);
  // Every LIN target is declared, with the same S bits (one configuration for the whole path).
  EXPECT_EQ(e6posStatusValues(dat).size(), 1u);
  EXPECT_EQ(count(src, "LIN XP"), count(dat, "DECL E6POS XP"));

  const fs::path tp = dir / "tp";
  const CliRun e = runCli({"export", dir.path().string(), "--format", "fanuc_tp", "-o", tp.string(), "--cell",
                           resource("cells/fanuc_m20ia_positioner.cell").string()});
  ASSERT_EQ(e.exitCode, 0) << e.err << e.out;
  bool found = false;
  for (const auto& f : fs::directory_iterator(tp)) {
    if (f.path().extension() != ".ls") continue;
    found = true;
    const std::string ls = readBytes(f.path());
    EXPECT_EQ(count(ls, ":  Arc Start["), 1u);  // instructions, not the header comment
    EXPECT_EQ(count(ls, ":  Arc End["), 1u);
    size_t lineCount = 0;
    ASSERT_TRUE(tpLineCount(ls, lineCount));
    const size_t mn = ls.find("/MN"), pos = ls.find("/POS");
    std::istringstream body(ls.substr(mn, pos - mn));
    size_t lines = 0;
    for (std::string line; std::getline(body, line);) lines += isNumberedTpLine(line);
    EXPECT_EQ(lineCount, lines);
  }
  EXPECT_TRUE(found);
}

// A plan folder whose trajectory.csv carries a dwell (the thermal re-planning's column): the program
// puts the arc out there, waits lifted and strikes again; the csv format keeps the column.
TEST(CliExport, ADwellInThePlanFolderWaitsInTheProgram)
{
  TempDir dir;
  const CliRun r =
      runCli({"plan", resource("samples/open_cylinder.stl").string(), "-o", dir.path().string()});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const std::string plain = readBytes(dir / "trajectory.csv");
  std::string withDwell;
  size_t row = 0, dwellRow = 0;
  for (size_t pos = 0; pos < plain.size(); ++row) {
    const size_t end = plain.find('\n', pos);
    const std::string line = plain.substr(pos, end - pos);
    pos = end + 1;
    if (dwellRow == 0 && row > 100 && line.find(",1,0") == line.size() - 4) dwellRow = row;  // arc on
    withDwell += line + (row == 0 ? ",dwell_s" : row == dwellRow ? ",20" : ",0") + "\n";
  }
  ASSERT_GT(dwellRow, 0u);
  // Written as the plan set it is part of (the folder's manifest refuses a file changed by hand).
  std::vector<OutputFile> set;
  for (const auto& f : fs::directory_iterator(dir.path()))
    if (f.is_regular_file() && f.path().filename() != kOutputManifest)
      set.push_back({f.path().filename().string(),
                     f.path().filename() == "trajectory.csv" ? withDwell : readBytes(f.path())});
  replaceOutputSet(dir.path(), OutputKind::Plan, set);

  const fs::path krl = dir / "krl";
  const CliRun e = runCli({"export", dir.path().string(), "--format", "krl", "-o", krl.string()});
  ASSERT_EQ(e.exitCode, 0) << e.err << e.out;
  EXPECT_NE(e.out.find("1 dwell(s)"), std::string::npos) << e.out;
  std::string src;
  for (const auto& f : fs::directory_iterator(krl))
    if (f.path().extension() == ".src") src += readBytes(f.path());
  EXPECT_EQ(count(src, "WAIT SEC 20.000"), 1u);
  EXPECT_EQ(count(src, "$OUT[1]=TRUE"), 2u);
  EXPECT_EQ(count(src, "$OUT[1]=FALSE"), 2u);

  const fs::path csv = dir / "csv";
  const CliRun c = runCli({"export", dir.path().string(), "--format", "csv", "-o", csv.string()});
  ASSERT_EQ(c.exitCode, 0) << c.err << c.out;
  const std::string written = readBytes(csv / "trajectory.csv");
  EXPECT_EQ(written.substr(0, written.find('\n')), withDwell.substr(0, withDwell.find('\n')));
  EXPECT_EQ(count(written, "\n"), count(withDwell, "\n"));
  EXPECT_EQ(count(written, ",20\n"), 1u);
  EXPECT_EQ(count(written, ",0\n"), row - 2);
}

TEST(CliExport, UnknownFormatsAndMissingPlansAreRefused)
{
  TempDir dir;
  EXPECT_EQ(runCli({"export", dir.path().string(), "--format", "abb", "-o", (dir / "x").string()}).exitCode,
            2);
  const CliRun noPlan =
      runCli({"export", dir.path().string(), "--format", "krl", "-o", (dir / "x").string()});
  EXPECT_EQ(noPlan.exitCode, 3) << noPlan.err;
  EXPECT_NE(noPlan.err.find("trajectory.csv"), std::string::npos) << noPlan.err;
}

}  // namespace
}  // namespace spira::test
