#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "spira/base/units.h"
#include "spira/planning/trajectory_csv_reader.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

fs::path resource(const std::string& sub)
{
  return sourceDir() / "resources" / sub;
}

struct JointRow {
  std::array<double, 6> q{};
  std::array<std::string, 2> e;
  std::string config;
  bool reachable = false, collision = false;
  double dexterity = 0.0;
};

std::vector<JointRow> readJoints(const fs::path& file, std::string& header)
{
  std::ifstream in(file);
  std::getline(in, header);
  std::vector<JointRow> rows;
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> cells = csvCells(line);
    EXPECT_EQ(cells.size(), 13u) << line;
    if (cells.size() != 13u) break;
    JointRow r;
    for (int k = 0; k < 6; ++k) r.q[k] = std::stod(cells[1 + k]);
    r.e = {cells[7], cells[8]};
    r.config = cells[9];
    r.reachable = cells[10] == "1";
    r.dexterity = std::stod(cells[11]);
    r.collision = cells[12] == "1";
    rows.push_back(r);
  }
  return rows;
}

// Every reachable row of joints.csv puts the TCP on its trajectory.csv point with the torch along
// -b (the spin about the torch axis is free, so only the axis is compared).
TEST(CliPlanCell, KukaJointsPutTheTorchOnEveryReachablePoint)
{
  TempDir dir;
  const CliRun r = runCli({"plan", resource("samples/dome.stl").string(), "-o", dir.path().string(), "--cell",
                           resource("cells/kuka_kr16_2_table.cell").string(), "--points-per-rev", "90"});
  ASSERT_TRUE(r.exitCode == 0 || r.exitCode == 4) << r.err << r.out;
  std::ifstream rin(dir / "report.json");
  const auto report = nlohmann::json::parse(rin);
  for (const char* key : {"cell", "reachable", "unreachable_points", "min_joint_limit_margin_deg",
                          "min_dexterity", "max_joint_speed_ratio", "collisions", "optimisation"})
    EXPECT_TRUE(report.contains(key)) << key;
  EXPECT_EQ(report["cell"], "KUKA KR 16-2 on a fixed table");
  EXPECT_EQ(r.exitCode == 0, report["reachable"].get<bool>() && report["feasible"].get<bool>() &&
                                 report["collisions"].get<int>() == 0);

  const Trajectory path = readTrajectoryCsv(dir / "trajectory.csv");
  std::string header;
  const auto joints = readJoints(dir / "joints.csv", header);
  EXPECT_EQ(header, "index,q1,q2,q3,q4,q5,q6,e1,e2,config,reachable,dexterity,collision");
  ASSERT_EQ(joints.size(), path.size());
  size_t unreachable = 0, checked = 0;
  const RobotCell cell(readCellFile(resource("cells/kuka_kr16_2_table.cell")));
  const Transform worldPart = cell.record().T_mount_part;
  for (size_t i = 0; i < joints.size(); ++i) {
    const JointRow& j = joints[i];
    EXPECT_TRUE(j.e[0].empty() && j.e[1].empty());
    EXPECT_EQ(j.config.front(), 'S');
    unreachable += !j.reachable;
    if (!j.reachable || i % 13) continue;
    const Transform tcp = cell.worldBase() * cell.arm().forward(cell.convention().fromControllerDeg(j.q)) *
                          cell.record().tool.T_flange_tcp;
    const TrajectoryPoint& p = path.points[i];
    EXPECT_LT((tcp.translation() - worldPart * p.position).norm(), 1e-6) << i;
    EXPECT_LT((tcp.linear().col(2) + worldPart.linear() * p.build).norm(), 1e-8) << i;
    ++checked;
  }
  EXPECT_EQ(unreachable, report["unreachable_points"].get<size_t>());
  EXPECT_GT(checked, 0u);
}

TEST(CliPlanCell, BadCellFailsBeforeAnythingIsWritten)
{
  TempDir dir;
  writeBytes(dir / "bad.cell", "{\"spira_cell\": 1, \"name\": \"x\"}");
  const auto out = dir / "plan";
  const CliRun r = runCli({"plan", resource("samples/dome.stl").string(), "-o", out.string(), "--cell",
                           (dir / "bad.cell").string()});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("bad.cell"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "trajectory.csv"));
}

}  // namespace
}  // namespace spira::test
