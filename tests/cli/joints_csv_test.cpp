#include <gtest/gtest.h>

#include <sstream>

#include "spira/planning/joints_csv.h"

namespace spira {
namespace {

std::vector<std::string> lines(const std::string& text)
{
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(JointsCsv, KukaRowsCarryStatusAndTurnAndLeaveExternalAxesEmpty)
{
  JointTrajectory j;
  j.controller = "kuka_krc4";
  JointPoint p;
  p.robotDeg = {10.5, -90, 90, 0, 45.25, -1e-3};
  p.kukaStatus = 2;
  p.kukaTurn = 35;
  p.dexterity = 0.125;
  j.points = {p, p};
  j.points[1].reachable = false;
  j.points[1].collision = true;
  const auto l = lines(jointsCsv(j));
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l[0], "index,q1,q2,q3,q4,q5,q6,e1,e2,config,reachable,dexterity,collision");
  EXPECT_EQ(l[1], "0,10.5,-90,90,0,45.25,-0.001,,,S2 T35,1,0.125,0");
  EXPECT_EQ(l[2], "1,10.5,-90,90,0,45.25,-0.001,,,S2 T35,0,0.125,1");
}

TEST(JointsCsv, FanucRowsQuoteTheConfigAndWriteThePositioner)
{
  JointTrajectory j;
  j.controller = "fanuc_r30ib";
  j.hasPositioner = true;
  JointPoint p;
  p.externalDeg = {-30, 720.5};
  p.fanucConfig = "N U T, 0, 0, 1";
  j.points = {p};
  const auto l = lines(jointsCsv(j));
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[1], "0,0,0,0,0,0,0,-30,720.5,\"N U T, 0, 0, 1\",1,1,0");
}

}  // namespace
}  // namespace spira
