#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "architecture/layering_check.h"
#include "support/test_support.h"

namespace spira {
namespace {

std::vector<std::string> described(const std::vector<layering::Violation>& violations)
{
  std::vector<std::string> out;
  for (const auto& v : violations) out.push_back(layering::describe(v));
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Layering, SourceTreeKeepsTheAllowedArrows)
{
  const auto violations = described(layering::checkTree(test::sourceDir()));
  EXPECT_TRUE(violations.empty()) << ::testing::PrintToString(violations);
}

TEST(Layering, EveryCrossingOfTheFixtureIsReportedWithItsFileAndLine)
{
  const auto root = test::sourceDir() / "tests" / "architecture" / "fixtures" / "crossing";
  const std::vector<std::string> expected = {
      "core/CMakeLists.txt:2: area mesh lists spira_path but includes none of its headers",
      "core/CMakeLists.txt:4: the DEPS form a cycle: mesh -> path -> mesh",
      "core/spira/mesh/mesh.cpp:3: area mesh includes tbb/parallel_for.h but core/CMakeLists.txt does not "
      "list "
      "TBB::tbb in its DEPS",
      "core/spira/mesh/mesh.cpp:5: area mesh includes spira/kinematics/robot.h but core/CMakeLists.txt does "
      "not "
      "list spira_kinematics in its DEPS",
      "core/spira/mesh/mesh.h:3: core includes QWidget: the core never uses Qt or VTK",
      "core/spira/path/path.h:4: core includes spira/ui/scene_view.h: the core never includes ui, app or "
      "plugin "
      "files",
      "examples/plugin_sdk/my_plugin.cpp:2: the example plugins include spira/path/path.h, which spira_sdk "
      "does not bring",
      "plugins/alpha/CMakeLists.txt:1: plugin alpha lists kinematics in AREAS but includes none of its "
      "headers",
      "plugins/alpha/CMakeLists.txt:1: plugin alpha lists mesh in AREAS, which spira_sdk brings",
      "plugins/alpha/alpha.cpp:2: plugin alpha includes beta/beta.h of plugin beta: plugins reach each other "
      "only "
      "through the registry",
      "plugins/alpha/alpha.cpp:3: plugin alpha includes spira/path/path.h but neither spira_sdk nor its "
      "AREAS "
      "list path",
      "plugins/alpha/tests/alpha_test.cpp:2: the tests of plugin alpha include ../alpha_internal.h, which is "
      "not one of its PUBLIC_HEADERS",
      "plugins/alpha/tests/alpha_test.cpp:3: plugin alpha includes beta/beta.h of plugin beta: plugins reach "
      "each other only through the registry",
      "tests/geometry/geometry_test.cpp:2: includes alpha/alpha_internal.h of plugin alpha, which is not one "
      "of its PUBLIC_HEADERS",
      "ui/spira/ui/window.cpp:2: ui includes builtin_plugins.h: the ui never includes plugin files (app/ "
      "passes "
      "the registry in)",
      "ui/spira/ui/window.cpp:3: ui includes alpha/alpha_settings.h: the ui never includes plugin files "
      "(app/ "
      "passes the registry in)",
  };
  EXPECT_EQ(described(layering::checkTree(root)), expected);
}

TEST(Layering, CoreAreasAreReadFromCoreCMakeLists)
{
  const auto areas = layering::readCoreAreas(test::sourceDir() / "core" / "CMakeLists.txt");
  ASSERT_TRUE(areas.count("robotcell"));
  EXPECT_FALSE(areas.at("robotcell").areas.count("document"));
  EXPECT_TRUE(areas.at("document").areas.count("robotcell"));
  EXPECT_TRUE(areas.at("base").areas.empty());
  EXPECT_TRUE(areas.at("skeleton").libraries.count("CGAL::CGAL"));
}

TEST(Layering, PluginsDeclareTheirAreasAndPublicHeaders)
{
  const auto sdk = layering::readSdkAreas(test::sourceDir() / "core" / "CMakeLists.txt");
  EXPECT_EQ(sdk, (std::set<std::string>{"base", "mesh", "path", "plugin"}));
  const auto envelope = layering::readPluginDeclaration(test::sourceDir() / "plugins" /
                                                        "decomposer_envelope" / "CMakeLists.txt");
  EXPECT_TRUE(envelope.areas.count("collision"));
  EXPECT_FALSE(envelope.areas.count("planning"));
  EXPECT_TRUE(envelope.publicHeaders.count("skeleton_fit.h"));
  EXPECT_FALSE(envelope.publicHeaders.count("ray_caster.h"));
}

}  // namespace
}  // namespace spira
