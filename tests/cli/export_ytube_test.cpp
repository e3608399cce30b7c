// spira-cli plan on a Y-shaped tube (three sub-paths) with --export: one arc per sub-path, the
// travel between them with the arc off, a PTP where the sub-path changes.
#include <gtest/gtest.h>

#include <functional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "planning/y_tube.h"
#include "spira/io/mesh_writers.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

TEST(ExportYTube, PlanWithExportWritesOneArcPerSubPath)
{
  TempDir dir;
  YTube y;
  y.top = 150.0;
  y.cell = 1.5;
  writeMesh(y.mesh(), dir / "ytube.stl");
  const fs::path out = dir / "plan";
  const CliRun r =
      runCli({"plan", (dir / "ytube.stl").string(), "-o", out.string(), "--cell",
              (sourceDir() / "resources/cells/kuka_kr16_2_table.cell").string(), "--points-per-rev", "90",
              "--export", "krl", "--program-name", "ytube", "--force", "--process-command", "speed_analog"});
  // Exit 4 (files written): the plan leaves some torch collisions unresolved and, tilted to avoid
  // the others, about 30 points of the leaning arms beyond A5's limit on this table cell, so the
  // export is refused unless forced (the bad-input rule); forced, each such move carries a
  // warning comment and the sub-path structure is complete.
  ASSERT_TRUE(r.exitCode == 0 || r.exitCode == 4) << r.err << r.out;
  const nlohmann::json report = nlohmann::json::parse(readBytes(out / "report.json"));
  EXPECT_EQ(report.value("n_paths", 0), 3);

  // Walk the main program and its parts in call order.
  std::vector<std::string> lines;
  std::function<void(const std::string&)> read = [&](const std::string& name) {
    std::istringstream src(readBytes(out / (name + ".src")));
    for (std::string line; std::getline(src, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.size() > 3 && line.compare(line.size() - 3, 3, "( )") == 0 && line.rfind("DEF ", 0) != 0)
        read(line.substr(0, line.size() - 3));
      else
        lines.push_back(line);
    }
  };
  read("ytube");
  // Triggers belong to the motion line after them; the arc burns from the start of the move with
  // the arc-on trigger to the end of the move with the arc-off one.
  size_t ons = 0, offs = 0, ptp = 0, outputsWhileOff = 0;
  bool arc = false;
  std::vector<std::string> triggers;
  for (const std::string& line : lines) {
    if (line.rfind("TRIGGER", 0) == 0) {
      triggers.push_back(line);
      continue;
    }
    const bool motion = line.rfind("LIN ", 0) == 0 || line.rfind("PTP ", 0) == 0;
    if (!motion) continue;
    bool on = false, off = false, output = false;
    for (const auto& t : triggers) {
      on = on || t.find("$OUT[1]=TRUE") != std::string::npos;
      off = off || t.find("$OUT[1]=FALSE") != std::string::npos;
      output = output || t.find("$ANOUT[") != std::string::npos;
    }
    triggers.clear();
    if (on) {
      EXPECT_FALSE(arc);
      arc = true;
      ++ons;
    }
    if (output && !arc) ++outputsWhileOff;
    if (line.rfind("PTP ", 0) == 0) {
      ++ptp;
      EXPECT_FALSE(arc) << "a joint move while the arc burns";
    }
    if (off) {
      EXPECT_TRUE(arc);
      arc = false;
      ++offs;
    }
  }
  EXPECT_EQ(ons, 3u);
  EXPECT_EQ(offs, 3u);
  EXPECT_EQ(ptp, 3u);  // the first move and one per change of sub-path
  EXPECT_EQ(outputsWhileOff, 0u);
  size_t flagged = 0;
  for (const std::string& line : lines) flagged += line.find("; WARNING (forced export)") == 0;
  if (!report.value("reachable", true) || report.value("collisions", 0) > 0) {
    EXPECT_GT(flagged, 0u);
  }
}

}  // namespace
}  // namespace spira::test
