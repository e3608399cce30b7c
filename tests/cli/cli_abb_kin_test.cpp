// `spira-cli kin` on the bundled ABB cell: axis names, confdata and the all-zero pose the URDF's joint
// origins give (x = 150 + 300 + 300 + 65, z = 486.5 + 700; resources/robots/README.md).
#include <gtest/gtest.h>

#include "cli_runner.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

TEST(CliAbbKin, ForwardKinematicsPrintsRapidAxesAndConfdata)
{
  const std::string cell = (sourceDir() / "resources/cells/abb_irb1600_positioner.cell").string();
  const CliRun zero = runCli({"kin", cell, "--fk", "0", "0", "0", "0", "0", "0"});
  ASSERT_EQ(zero.exitCode, 0) << zero.err;
  EXPECT_NE(zero.out.find("(abb_irc5)"), std::string::npos) << zero.out;
  EXPECT_NE(zero.out.find("flange: X 815.0000  Y 0.0000  Z 1186.5000"), std::string::npos) << zero.out;
  EXPECT_NE(zero.out.find("tcp   : X 1165.0000  Y 0.0000  Z 1186.5000"), std::string::npos) << zero.out;
  EXPECT_NE(zero.out.find("rax_6 0.0000  confdata [0,0,0,0]"), std::string::npos) << zero.out;
  // Axis 1 at -10 deg is quadrant -1, axis 4 at 95 quadrant 1, axis 6 at -270 quadrant -3, axis 5
  // negative sets bit 0 of cfx.
  const CliRun turned = runCli({"kin", cell, "--fk", "-10", "20", "-30", "95", "-40", "-270"});
  ASSERT_EQ(turned.exitCode, 0) << turned.err;
  EXPECT_NE(turned.out.find("confdata [-1,1,-3,1]"), std::string::npos) << turned.out;
}

}  // namespace
}  // namespace spira::test
