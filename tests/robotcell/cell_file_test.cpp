#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/robotcell/cell_file.h"
#include "support/test_support.h"

namespace spira {
namespace {

namespace fs = std::filesystem;

fs::path cellsDir()
{
  return test::sourceDir() / "resources" / "cells";
}

TEST(CellFile, BundledKukaCellLoadsWithItsRobotAndLimits)
{
  const CellRecord c = readCellFile(cellsDir() / "kuka_kr16_2_table.cell");
  EXPECT_EQ(c.controller, ControllerFamily::KukaKrc4);
  EXPECT_TRUE(fs::exists(c.robotUrdf)) << c.robotUrdf;
  EXPECT_EQ(fs::path(c.robotUrdf).filename(), "robot.urdf");
  EXPECT_FALSE(c.hasPositioner());
  EXPECT_EQ(c.mounting, PartMounting::FixedTable);
  ASSERT_EQ(c.robotAxes.size(), 6u);
  EXPECT_EQ(c.robotAxes[1].urdfJoint, "joint_a2");
  EXPECT_EQ(c.robotAxes[1].minDeg, -155.0);  // README table, KR 16-2 A2
  EXPECT_EQ(c.robotAxes[1].maxDeg, 35.0);
  EXPECT_EQ(c.robotAxes[5].maxSpeedDegPerS, 615.0);
  EXPECT_NEAR((c.tool.T_flange_tcp.translation() - Vec3(0, 0, 350)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((c.T_mount_part.translation() - Vec3(1100, 0, 400)).norm(), 0.0, 1e-12);
}

TEST(CellFile, BundledFanucCellHasThePositionerAndTheJ23Linkage)
{
  const CellRecord c = readCellFile(cellsDir() / "fanuc_m20ia_positioner.cell");
  EXPECT_EQ(c.controller, ControllerFamily::FanucR30iB);
  EXPECT_EQ(c.robotBaseLink, "base");
  EXPECT_EQ(c.j23Coupling, 1);
  ASSERT_TRUE(c.hasPositioner());
  EXPECT_TRUE(fs::exists(c.positionerUrdf)) << c.positionerUrdf;
  EXPECT_EQ(c.mounting, PartMounting::Positioner);
  EXPECT_TRUE(c.keepBuildVertical);
  ASSERT_EQ(c.positionerAxes.size(), 2u);
  EXPECT_EQ(c.positionerAxes[0].urdfJoint, "joint_e1");
  EXPECT_TRUE(fs::exists(fs::path(c.robotUrdf).parent_path() / "LICENSE-upstream"));
}

TEST(CellFile, TextRoundTripKeepsEveryFieldAndPose)
{
  const fs::path dir = cellsDir();
  for (const char* name : {"kuka_kr16_2_table.cell", "fanuc_m20ia_positioner.cell"}) {
    CellRecord c = readCellFile(dir / name);
    // A pose with every angle non-zero, and one at pitch 90 degrees (gimbal lock of rpy).
    c.T_world_robotbase = transformFromXyzRpy(Vec3(10.5, -20.25, 3.0), Vec3(0.3, -0.7, 2.9));
    c.tool.T_flange_tcp = transformFromXyzRpy(Vec3(0, 12.0, 400.0), Vec3(0.2, kPi / 2, -0.4));
    const CellRecord back = cellFromText(cellFileText(c, dir), dir);
    EXPECT_EQ(back.name, c.name);
    EXPECT_EQ(back.robotUrdf, c.robotUrdf);
    EXPECT_EQ(back.robotAxes, c.robotAxes);
    EXPECT_EQ(back.positionerAxes, c.positionerAxes);
    EXPECT_LT((back.T_world_robotbase.matrix() - c.T_world_robotbase.matrix()).norm(), 1e-12);
    EXPECT_LT((back.tool.T_flange_tcp.matrix() - c.tool.T_flange_tcp.matrix()).norm(), 1e-12);
    EXPECT_LT((back.T_mount_part.matrix() - c.T_mount_part.matrix()).norm(), 1e-12);
  }
}

void expectRejected(const std::string& text, const std::string& mentions)
{
  try {
    cellFromText(text, "/tmp");
    FAIL() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(mentions), std::string::npos) << e.what();
    EXPECT_FALSE(e.hint().empty());
  }
}

std::string minimalCell(const std::string& robotExtra, const std::string& rest)
{
  std::string axes;
  for (int i = 1; i <= 6; ++i)
    axes += std::string(i > 1 ? "," : "") + R"({"joint": "j)" + std::to_string(i) +
            R"(", "min_deg": -90, "max_deg": 90, "max_speed_deg_s": 100})";
  return R"({"spira_cell": 1, "name": "t", "controller": "kuka_krc4", "robot": {"urdf": "r.urdf", )" +
         robotExtra + R"("axes": [)" + axes + R"(]}, "tool": {})" + (rest.empty() ? "" : ", " + rest) + "}";
}

TEST(CellFile, BadFilesAreRefusedNamingTheField)
{
  EXPECT_NO_THROW(cellFromText(minimalCell("", R"("part": {})"), "/tmp"));
  EXPECT_EQ(cellFromText(minimalCell("", R"("part": {})"), "/tmp").robotUrdf, "/tmp/r.urdf");
  expectRejected("{ not json", "not valid JSON");
  expectRejected(R"({"spira_cell": 2})", "version 2");
  expectRejected(R"({"spira_cell": 2.5})", "version 2.5 is not supported");
  expectRejected(R"({"spira_cell": 77777777777777777777777777777771})",
                 "version 7.77778e+31 is not supported");
  expectRejected(minimalCell("", R"("part": {"mount": "positioner"})"), "no positioner");
  expectRejected(minimalCell("", R"("part": {"mount": "ceiling"})"), "ceiling");
  expectRejected(minimalCell(R"("j23_coupling": 2, )", R"("part": {})"), "j23_coupling");
  expectRejected(minimalCell(R"("pose": {"xyz_mm": [1, 2]}, )", R"("part": {})"), "xyz_mm");
  expectRejected(minimalCell("", ""), "'part' is missing");
  std::string fiveAxes = minimalCell("", R"("part": {})");
  fiveAxes.replace(fiveAxes.find(R"({"joint": "j6")"), 0, "");
  const auto at = fiveAxes.find(R"(,{"joint": "j6")");
  fiveAxes.erase(at, fiveAxes.find('}', at) - at + 1);
  expectRejected(fiveAxes, "6 axes");
}

}  // namespace
}  // namespace spira
