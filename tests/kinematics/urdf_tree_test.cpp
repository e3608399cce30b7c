// urdfdom builds the links of a joint loop into a cycle it never frees before refusing the file
// (found by the URDF fuzz target under LeakSanitizer): parseUrdfModel refuses such files first.
#include <gtest/gtest.h>

#include <string>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/kinematics/urdf_parse.h"
#include "support/test_support.h"

#include <urdf_model/model.h>

namespace spira::test {
namespace {

std::string robot(const std::string& joints)
{
  return "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>" + joints + "</robot>";
}

std::string joint(const std::string& name, const std::string& parent, const std::string& child)
{
  return "<joint name=\"" + name + "\" type=\"fixed\"><parent link=\"" + parent + "\"/><child link=\"" +
         child + "\"/></joint>";
}

std::string refusal(const std::string& xml)
{
  try {
    parseUrdfModel(xml, "r.urdf");
    return "parsed";
  } catch (const InputError& e) {
    return e.what();
  }
}

TEST(UrdfTree, ATreeParses)
{
  EXPECT_EQ(refusal(robot(joint("j1", "a", "b") + joint("j2", "b", "c"))), "parsed");
  EXPECT_EQ(refusal(robot(joint("j1", "a", "b") + joint("j2", "a", "c"))), "parsed");
  const auto model =
      parseUrdfModel(readFile(sourceDir() / "resources/robots/kuka_kr16_2/robot.urdf"), "kuka");
  ASSERT_TRUE(model);
  EXPECT_EQ(model->getRoot()->name, "base_link");
}

TEST(UrdfTree, LoopsAreRefusedNamingALinkAndItsJoint)
{
  EXPECT_EQ(refusal(robot(joint("j1", "a", "b") + joint("j2", "b", "a"))),
            "r.urdf: the joints form a loop through link 'a' (joint 'j2')");
  EXPECT_EQ(refusal(robot(joint("j1", "a", "b") + joint("j2", "b", "c") + joint("j3", "c", "a"))),
            "r.urdf: the joints form a loop through link 'a' (joint 'j3')");
  EXPECT_EQ(refusal(robot(joint("self", "b", "b"))),
            "r.urdf: the joints form a loop through link 'b' (joint 'self')");
}

TEST(UrdfTree, ALinkWithTwoParentsIsRefused)
{
  EXPECT_EQ(refusal(robot(joint("j1", "a", "c") + joint("j2", "b", "c"))),
            "r.urdf: link 'c' is the child of two joints ('j1' and 'j2')");
}

// urdfdom's own first error ends the message; it prints nothing itself.
TEST(UrdfTree, UrdfdomsFirstErrorIsInTheMessage)
{
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(refusal("<plant/>"),
            "r.urdf is not valid URDF: Could not find the 'robot' element in the xml file");
  EXPECT_EQ(refusal(robot(joint("j1", "a", "z"))),
            "r.urdf is not valid URDF: Failed to build tree: child link [z] of joint [j1] not found");
  EXPECT_EQ(refusal("<robot"), "r.urdf is not valid URDF: Failed to read Element name");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace spira::test
