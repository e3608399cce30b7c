// Bad robot descriptions behind a cell (issue 4, "Bad input"): a URDF that does not parse stops the
// cell with a clear error; a chain that is not a 6R arm with a spherical wrist keeps the cell for
// forward kinematics and display but refuses the inverse kinematics with the reason; missing meshes
// get stand-ins and warnings.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
#include "spira/robotcell/robot_collision_model.h"
#include "support/test_support.h"

namespace spira {
namespace {

namespace fs = std::filesystem;

CellRecord kukaCell()
{
  return readCellFile(test::sourceDir() / "resources" / "cells" / "kuka_kr16_2_table.cell");
}

std::string kukaUrdfText()
{
  return test::readBytes(test::sourceDir() / "resources" / "robots" / "kuka_kr16_2" / "robot.urdf");
}

// The KR 16-2 with axis 5 moved 50 mm up (+z of link_4) off axis 4: axes 4, 5 and 6 no longer meet.
std::string offsetWristUrdf()
{
  std::string text = kukaUrdfText();
  const std::string a5 = "<origin xyz=\"0 0 0\" rpy=\"0 0 0\" />\n    <parent link=\"link_4\" />";
  const size_t at = text.find(a5);
  if (at == std::string::npos) return std::string();
  text.replace(at, a5.size(), "<origin xyz=\"0 0 0.05\" rpy=\"0 0 0\" />\n    <parent link=\"link_4\" />");
  return text;
}

Mat3 rx(double a)
{
  return Eigen::AngleAxisd(a, Vec3::UnitX()).toRotationMatrix();
}
Mat3 ry(double a)
{
  return Eigen::AngleAxisd(a, Vec3::UnitY()).toRotationMatrix();
}
Mat3 rz(double a)
{
  return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix();
}

// T_base_tool0 of that offset-wrist arm composed by hand from the URDF's numbers (mm): A1 about -z
// 675 up, A2 about y 260 out, A3 about y 680 out, A4 about -x at (670, 0, -35), A5 about y 50 above
// A4's axis, A6 about -x, flange 158 out, tool0 = flange turned so z points out of it.
Transform handComposed(const JointVector& q)
{
  Mat3 r = rz(-q[0]);
  Vec3 p = Vec3(0, 0, 675);
  const auto step = [&](const Vec3& offset, const Mat3& turn) {
    p += r * offset;
    r = r * turn;
  };
  step(Vec3(260, 0, 0), ry(q[1]));
  step(Vec3(680, 0, 0), ry(q[2]));
  step(Vec3(670, 0, -35), rx(-q[3]));
  step(Vec3(0, 0, 50), ry(q[4]));
  step(Vec3::Zero(), rx(-q[5]));
  step(Vec3(158, 0, 0), Mat3::Identity());
  Transform t = Transform::Identity();
  t.translation() = p;
  t.linear() = r;
  return t;
}

TEST(RobotCellBadInput, AUrdfThatDoesNotParseStopsTheCellWithAClearError)
{
  test::TempDir dir;
  test::writeBytes(dir / "robot.urdf", "<robot name='broken'><link name='base_link'/><joint name=");
  CellRecord c = kukaCell();
  c.robotUrdf = (dir / "robot.urdf").string();
  try {
    RobotCell cell(c);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("not valid URDF"), std::string::npos) << what;
    EXPECT_FALSE(e.hint().empty());
  }
  // An empty file and a file that is not XML at all fail the same way, never with a crash.
  for (const char* bytes : {"", "solid cube\nendsolid cube\n"}) {
    test::writeBytes(dir / "robot.urdf", bytes);
    EXPECT_THROW(RobotCell{c}, InputError) << '"' << bytes << '"';
  }
}

TEST(RobotCellBadInput, ANonSphericalWristKeepsForwardKinematicsButRefusesTheIk)
{
  const std::string urdf = offsetWristUrdf();
  ASSERT_FALSE(urdf.empty()) << "joint_a5's origin not found in the KR 16-2 URDF";
  test::TempDir dir;
  test::writeBytes(dir / "robot.urdf", urdf);  // no meshes next to it: stand-ins for display
  CellRecord c = kukaCell();
  c.robotUrdf = (dir / "robot.urdf").string();
  const RobotCell cell(c);

  EXPECT_FALSE(cell.canSolve());
  EXPECT_NE(cell.ikRefusal().find("no spherical wrist"), std::string::npos) << cell.ikRefusal();
  try {
    cell.ik();
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cannot solve joint motion"), std::string::npos) << what;
    EXPECT_NE(what.find("axes 4, 5 and 6 do not meet"), std::string::npos) << what;
    EXPECT_FALSE(e.hint().empty());
  }

  // Forward kinematics still work, and they are the offset arm's (not the original's).
  for (const JointVector& q : {JointVector(JointVector::Zero()), JointVector(0.3, -1.2, 0.9, -2.0, 0.7, 1.4),
                               JointVector(-1.0, -0.4, 1.8, 2.5, -1.9, -3.0)}) {
    const Transform fk = cell.arm().forward(q);
    const Transform hand = handComposed(q);
    EXPECT_LT((fk.translation() - hand.translation()).norm(), 1e-9);
    // tool0 is the flange turned by rpy (0, pi/2, 0): its z along the flange's x.
    EXPECT_LT((fk.linear().col(2) - hand.linear().col(0)).norm(), 1e-12);
  }
  EXPECT_LT((cell.arm().forward(JointVector::Zero()).translation() - Vec3(1768, 0, 690)).norm(), 1e-9);

  // The cell still displays: every link has a shape (stand-in cubes for the missing meshes), and
  // each missing mesh is a warning, not an error.
  const TriangleMesh part = makeOpenCylinder(50, 100, 32, 4);
  const RobotCollisionModel model(cell, part);
  EXPECT_FALSE(model.warnings().empty());
  bool namesAMesh = false;
  for (const std::string& w : model.warnings())
    namesAMesh = namesAMesh || w.find(".stl") != std::string::npos;
  EXPECT_TRUE(namesAMesh) << model.warnings().front();
  EXPECT_NO_THROW(model.armHits(JointVector::Zero(), cell.setup().basePart, Eigen::Vector2d::Zero()));
}

}  // namespace
}  // namespace spira
