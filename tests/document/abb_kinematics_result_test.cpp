#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "document_test_data.h"
#include "spira/base/error.h"
#include "spira/document/project_file.h"
#include "spira/document/results.h"

namespace spira {
namespace {

// An ABB solution keeps its confdata and its tool in the project; other controllers' files keep
// their keys unchanged.
TEST(AbbKinematicsResult, ConfdataAndToolRoundTrip)
{
  DocumentState s = test::fullState();
  ASSERT_TRUE(s.results.kinematics);
  EXPECT_FALSE(resultsToJson(s.results)["kinematics"]["joints"].contains("abb_conf"));
  KinematicsResult k = *s.results.kinematics;
  k.joints.controller = "abb_irc5";
  k.joints.flangeTcp.translation() = Vec3(1.5, -2.0, 350.0);
  for (size_t i = 0; i < k.joints.size(); ++i)
    k.joints.points[i].abbConf = {static_cast<int>(i) - 3, -1, 2, static_cast<int>(i % 8)};
  s.results.kinematics = std::make_shared<const KinematicsResult>(k);
  const DocumentState back = decodeProject(encodeProject(s));
  ASSERT_TRUE(back.results.kinematics);
  EXPECT_EQ(*back.results.kinematics, k);
  EXPECT_EQ(back.results.kinematics->joints.points[6].abbConf, (std::array<int, 4>{{3, -1, 2, 6}}));
  EXPECT_EQ(back.results.kinematics->joints.flangeTcp.translation(), Vec3(1.5, -2.0, 350.0));
  // A changed confdata or tool is seen by ==.
  KinematicsResult c = *back.results.kinematics;
  c.joints.points[2].abbConf[3] = 5;
  EXPECT_NE(c, k);
  c = *back.results.kinematics;
  c.joints.flangeTcp.translation().z() = 351.0;
  EXPECT_NE(c, k);
  nlohmann::json j = resultsToJson(s.results);
  j["kinematics"]["joints"]["abb_conf"] = j["kinematics"]["joints"]["kuka_turn"];  // 1 int per point, not 4
  EXPECT_THROW(resultsFromJson(j), InputError);
}

}  // namespace
}  // namespace spira
