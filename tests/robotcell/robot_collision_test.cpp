#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/link_shapes.h"
#include "spira/robotcell/robot_collision_model.h"
#include "support/test_support.h"

namespace spira {
namespace {

namespace fs = std::filesystem;

fs::path robots()
{
  return test::sourceDir() / "resources" / "robots";
}

CellRecord kukaCell()
{
  return readCellFile(test::sourceDir() / "resources" / "cells" / "kuka_kr16_2_table.cell");
}

TEST(LinkShapes, KukaLinksComeWithTheirCollisionMeshesInMillimetres)
{
  const RobotShapes s =
      readRobotShapes((robots() / "kuka_kr16_2" / "robot.urdf").string(), "base_link", "tool0");
  EXPECT_TRUE(s.warnings.empty());
  std::vector<std::string> names;
  for (const LinkShape& l : s.links) names.push_back(l.link);
  for (const char* n : {"base_link", "link_1", "link_2", "link_3", "link_4", "link_5", "link_6"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  for (const LinkShape& l : s.links) {
    EXPECT_FALSE(l.standInCube);
    if (l.link == "link_2") {
      // The upper arm spans A2 -> A3, 680 mm.
      Vec3 lo = Vec3::Constant(1e9), hi = -lo;
      for (const Vec3& v : l.mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
      EXPECT_GT((hi - lo).maxCoeff(), 600.0);
      EXPECT_LT((hi - lo).maxCoeff(), 1000.0);
      EXPECT_EQ(l.joints, 2u);
    }
  }
}

TEST(LinkShapes, MissingMeshesGetAStandInCubeAndAWarning)
{
  test::TempDir dir;
  const std::string urdf = test::readBytes(robots() / "kuka_kr16_2" / "robot.urdf");
  test::writeBytes(dir / "robot.urdf", urdf);  // the meshes are not next to this copy
  const RobotShapes s = readRobotShapes((dir / "robot.urdf").string(), "base_link", "tool0");
  EXPECT_FALSE(s.warnings.empty());
  ASSERT_FALSE(s.links.empty());
  for (const LinkShape& l : s.links) EXPECT_TRUE(l.standInCube);
  EXPECT_NE(s.warnings.front().find("missing"), std::string::npos);
}

TEST(RobotCollisionModel, UpperArmHitsAPartPlacedAcrossItAndNothingHitsAFarPart)
{
  const RobotCell cell(kukaCell());
  const TriangleMesh part = makeOpenCylinder(80.0, 200.0, 48, 8);
  const RobotCollisionModel model(cell, part);
  const JointVector home = cell.convention().fromControllerDeg({0, -90, 90, 0, 0, 0});
  // At HOME the upper arm stands vertical from (260, 0, 675) to (260, 0, 1355).
  Transform across = Transform::Identity();
  across.translation() = Vec3(260, 0, 900);
  const auto hits = model.armHits(home, across, Eigen::Vector2d::Zero());
  EXPECT_NE(std::find(hits.begin(), hits.end(), "link_2"), hits.end());
  Transform far = Transform::Identity();
  far.translation() = Vec3(3000, 0, 0);
  EXPECT_TRUE(model.armHits(home, far, Eigen::Vector2d::Zero()).empty());
  // 100 mm in front of the stretched-forward flange at HOME (1088, 0, 1320), clear of every link.
  Transform ahead = Transform::Identity();
  ahead.translation() = Vec3(1450, 0, 1200);
  EXPECT_TRUE(model.armHits(home, ahead, Eigen::Vector2d::Zero(), 0.0).empty());
}

}  // namespace
}  // namespace spira
