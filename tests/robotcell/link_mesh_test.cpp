#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "spira/base/error.h"
#include "spira/robotcell/link_shapes.h"
#include "spira/robotcell/mesh_file.h"
#include "support/test_support.h"

namespace spira {
namespace {

namespace fs = std::filesystem;

fs::path kuka()
{
  return test::sourceDir() / "resources" / "robots" / "kuka_kr16_2";
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The vendor's package draws each link twice: a detailed COLLADA visual and a coarser STL collision
// hull. Read independently, both must fill the same box in the link frame.
TEST(LinkMesh, KukaVisualColladaAndCollisionStlFillTheSameBox)
{
  const RobotShapes s = readRobotShapes((kuka() / "robot.urdf").string(), "base_link", "tool0");
  EXPECT_TRUE(s.warnings.empty()) << (s.warnings.empty() ? "" : s.warnings.front());
  int compared = 0;
  for (const LinkShape& l : s.links) {
    if (l.link.rfind("link_", 0) != 0 && l.link != "base_link") continue;
    ASSERT_TRUE(l.displayIsVisual) << l.link;
    EXPECT_FALSE(l.standInCube) << l.link;
    const BoundingBox visual = l.display.bounds(), collision = l.mesh.bounds();
    EXPECT_GT(visual.diagonal(), 100.0) << l.link;  // the flange (link_6) is the smallest, 111 mm
    const Vec3 dMin = visual.min - collision.min, dMax = visual.max - collision.max;
    std::cout << l.link << ": visual " << visual.size().transpose() << " mm, |dmin| "
              << dMin.cwiseAbs().transpose() << ", |dmax| " << dMax.cwiseAbs().transpose() << ", triangles "
              << l.display.faceCount() << " visual / " << l.mesh.faceCount() << " collision\n";
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(visual.min[k], collision.min[k], 15.0) << l.link << " axis " << k;
      EXPECT_NEAR(visual.max[k], collision.max[k], 15.0) << l.link << " axis " << k;
    }
    ++compared;
  }
  EXPECT_EQ(compared, 7);
}

TEST(LinkMesh, ColladaUnitIsHonouredAndUpAxisIgnoredAsRvizDoes)
{
  const fs::path source = kuka() / "meshes" / "visual" / "link_2.dae";
  const BoundingBox metres = readLinkMesh(source, Vec3::Ones()).bounds();
  test::TempDir dir;
  const std::string text = test::readBytes(source);
  test::writeBytes(dir / "mm.dae", replaced(text, "meter=\"1\"", "meter=\"0.001\""));
  test::writeBytes(dir / "yup.dae", replaced(text, "<up_axis>Z_UP</up_axis>", "<up_axis>Y_UP</up_axis>"));
  const BoundingBox millimetres = readLinkMesh(dir / "mm.dae", Vec3::Ones()).bounds();
  const BoundingBox yUp = readLinkMesh(dir / "yup.dae", Vec3::Ones()).bounds();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(millimetres.min[k], 0.001 * metres.min[k], 1e-6) << k;
    EXPECT_NEAR(millimetres.max[k], 0.001 * metres.max[k], 1e-6) << k;
    EXPECT_NEAR(yUp.min[k], metres.min[k], 1e-6) << k;
    EXPECT_NEAR(yUp.max[k], metres.max[k], 1e-6) << k;
  }
  // The URDF scale multiplies per axis, after the unit.
  const BoundingBox scaled = readLinkMesh(source, Vec3(2.0, 1.0, 0.5)).bounds();
  EXPECT_NEAR(scaled.max.x(), 2.0 * metres.max.x(), 1e-6);
  EXPECT_NEAR(scaled.min.z(), 0.5 * metres.min.z(), 1e-6);
  EXPECT_NEAR(scaled.max.y(), metres.max.y(), 1e-6);
}

// COLLADA is parsed by Assimp in the spira-import helper, never in this process: the whole KUKA
// package is read without libassimp being loaded here, and a reader stopped by the import limits
// comes back as an InputError naming the file, with a hint about the robot package.
TEST(LinkMesh, ColladaIsReadInTheImportHelper)
{
  const RobotShapes s = readRobotShapes((kuka() / "robot.urdf").string(), "base_link", "tool0");
  ASSERT_FALSE(s.links.empty());
  EXPECT_TRUE(s.links.front().displayIsVisual);
  const std::string maps = test::readBytes("/proc/self/maps");
  ASSERT_NE(maps.find("libc"), std::string::npos);
  EXPECT_EQ(maps.find("libassimp"), std::string::npos) << "Assimp is loaded in the planning process";

  // A limit no read meets: a warm helper read this small file within 1 ms now and then (CI).
  ::setenv("SPIRA_IMPORT_TIMEOUT_S", "1e-9", 1);
  try {
    readLinkMesh(kuka() / "meshes" / "visual" / "link_2.dae", Vec3::Ones());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("reading 'link_2.dae' took longer than the import's time limit"),
              std::string::npos)
        << e.what();
    EXPECT_NE(e.hint().find("robot's support package"), std::string::npos) << e.hint();
  }
  ::unsetenv("SPIRA_IMPORT_TIMEOUT_S");
}

TEST(LinkMesh, CorruptOrMissingFileThrowsIoError)
{
  test::TempDir dir;
  test::writeBytes(dir / "broken.dae", "<?xml version=\"1.0\"?><COLLADA><library_geometries><geometry");
  EXPECT_THROW(readLinkMesh(dir / "broken.dae", Vec3::Ones()), IoError);
  EXPECT_THROW(readLinkMesh(dir / "absent.dae", Vec3::Ones()), IoError);
}

// A one-joint arm whose collision and visual meshes are both corrupt COLLADA: the link keeps a
// stand-in cube for collision and display, with one warning per file, and nothing throws.
TEST(LinkMesh, CorruptColladaGivesTheStandInAndWarnings)
{
  test::TempDir dir;
  test::writeBytes(dir / "broken.dae", "<?xml version=\"1.0\"?><COLLADA version=\"1.4.1\"><asset><unit");
  test::writeBytes(dir / "arm.urdf", R"(<?xml version="1.0"?>
<robot name="arm">
  <link name="base_link"/>
  <link name="link_1">
    <visual><origin xyz="0 0 0.2" rpy="0 0 0"/><geometry><mesh filename="broken.dae"/></geometry></visual>
    <collision><origin xyz="0 0 0.1" rpy="0 0 0"/><geometry><mesh filename="broken.dae"/></geometry></collision>
  </link>
  <joint name="joint_1" type="revolute">
    <parent link="base_link"/><child link="link_1"/><origin xyz="0 0 0.5" rpy="0 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
</robot>)");
  RobotShapes s;
  ASSERT_NO_THROW(s = readRobotShapes((dir / "arm.urdf").string(), "base_link", "link_1"));
  ASSERT_EQ(s.links.size(), 1u);
  const LinkShape& l = s.links.front();
  EXPECT_TRUE(l.standInCube);
  EXPECT_FALSE(l.displayIsVisual);
  const BoundingBox box = l.display.bounds();
  EXPECT_NEAR(box.size().x(), 100.0, 1e-9);
  EXPECT_NEAR(box.center().z(), 100.0, 1e-9);  // the collision origin, 0.1 m
  EXPECT_EQ(l.display, l.mesh);
  ASSERT_EQ(s.warnings.size(), 2u);
  EXPECT_NE(s.warnings[0].find("collision geometry"), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[1].find("visual geometry"), std::string::npos) << s.warnings[1];
  for (const std::string& w : s.warnings) EXPECT_NE(w.find("broken.dae"), std::string::npos) << w;
}

}  // namespace
}  // namespace spira
