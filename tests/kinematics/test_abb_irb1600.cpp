#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "robot_files.h"
#include "spira/base/units.h"
#include "spira/kinematics/abb_confdata.h"
#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/controller_convention.h"
#include "spira/kinematics/opw_detection.h"

namespace spira {
namespace {

using test::positionGap;
using test::robotUrdf;
using test::rotationGap;

// The bundled IRB 1600 URDF evaluated without Spira's reader (or urdfdom): its <joint> elements are
// read with regular expressions and the chain base_link -> tool0 is composed with Eigen as the URDF
// specification defines it: T = Trans(xyz) * Rz(y) Ry(p) Rx(r) * Rot(axis, q) for each joint.
struct XmlJoint {
  std::string name, type, parent, child;
  Vec3 xyz = Vec3::Zero(), rpy = Vec3::Zero(), axis = Vec3::UnitX();
};

Vec3 threeNumbers(const std::string& text)
{
  std::istringstream in(text);
  Vec3 v;
  in >> v.x() >> v.y() >> v.z();
  return v;
}

std::string attribute(const std::string& element, const std::string& tag, const std::string& name)
{
  std::smatch m;
  const std::regex re("<" + tag + "\\b[^>]*\\b" + name + "=\"([^\"]*)\"");
  return std::regex_search(element, m, re) ? m[1].str() : std::string();
}

class IndependentUrdf {
 public:
  explicit IndependentUrdf(const std::string& file)
  {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    const std::regex jointRe("<joint\\b[\\s\\S]*?</joint>");
    for (auto it = std::sregex_iterator(s.begin(), s.end(), jointRe); it != std::sregex_iterator(); ++it) {
      const std::string e = it->str();
      XmlJoint j;
      j.name = attribute(e, "joint", "name");
      j.type = attribute(e, "joint", "type");
      j.parent = attribute(e, "parent", "link");
      j.child = attribute(e, "child", "link");
      if (!attribute(e, "origin", "xyz").empty())
        j.xyz = threeNumbers(attribute(e, "origin", "xyz")) * 1000.0;
      if (!attribute(e, "origin", "rpy").empty()) j.rpy = threeNumbers(attribute(e, "origin", "rpy"));
      if (!attribute(e, "axis", "xyz").empty()) j.axis = threeNumbers(attribute(e, "axis", "xyz"));
      byChild_[j.child] = j;
    }
  }

  // base_link -> `tip` with the revolute joints joint_1..joint_6 at q.
  Transform forward(const JointVector& q, const std::string& tip = "tool0") const
  {
    Transform t = Transform::Identity();
    for (std::string link = tip; link != "base_link";) {
      const XmlJoint& j = byChild_.at(link);
      Transform step = Transform::Identity();
      step.translate(j.xyz);
      step.rotate(Eigen::AngleAxisd(j.rpy.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(j.rpy.y(), Vec3::UnitY()) *
                  Eigen::AngleAxisd(j.rpy.x(), Vec3::UnitX()));
      if (j.type == "revolute") step.rotate(Eigen::AngleAxisd(q[j.name.back() - '1'], j.axis.normalized()));
      t = step * t;
      link = j.parent;
    }
    return t;
  }

  size_t jointCount() const { return byChild_.size(); }

 private:
  std::map<std::string, XmlJoint> byChild_;
};

JointVector deg(double a, double b, double c, double d, double e, double f)
{
  JointVector q;
  q << degToRad(a), degToRad(b), degToRad(c), degToRad(d), degToRad(e), degToRad(f);
  return q;
}

KinematicChain irb1600()
{
  return KinematicChain::fromUrdfFile(robotUrdf("abb_irb1600_8_145"), "base_link", "tool0");
}

JointVector randomWithinLimits(const KinematicChain& c, std::mt19937& rng)
{
  JointVector q;
  for (int i = 0; i < 6; ++i) {
    const ChainJoint& j = c.joint(static_cast<size_t>(i));
    q[i] = std::uniform_real_distribution<double>(j.lower, j.upper)(rng);
  }
  return q;
}

TEST(AbbIrb1600, ForwardKinematicsEqualsAnIndependentEvaluationOfTheUrdf)
{
  const IndependentUrdf urdf(robotUrdf("abb_irb1600_8_145"));
  ASSERT_EQ(urdf.jointCount(), 9u);  // 6 revolute + base, flange, tool0
  const KinematicChain c = irb1600();
  // README check value: all-zero = upper arm vertical, forearm horizontal, tool0 Z forward at
  // x = 150 + 300 + 300 + 65, z = 486.5 + 700.
  const Transform zero = c.forward(JointVector::Zero());
  EXPECT_NEAR((zero.translation() - Vec3(815, 0, 1186.5)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((zero.linear() * Vec3::UnitZ() - Vec3::UnitX()).norm(), 0.0, 1e-12);
  double worst = 0.0;
  for (const JointVector& q :
       {deg(0, 0, 0, 0, 0, 0), deg(30, -20, 40, 90, -45, 180), deg(-170, 110, -240, -190, 110, 390),
        deg(90, 45, -90, 45, 90, -45), deg(-45, -85, 60, 10, -10, 300)}) {
    const Transform a = c.forward(q), b = urdf.forward(q);
    worst = std::max(worst, positionGap(a, b));
    EXPECT_LT(rotationGap(a, b), 1e-12);
  }
  std::mt19937 rng(16);
  for (int k = 0; k < 500; ++k) {
    const JointVector q = randomWithinLimits(c, rng);
    const Transform a = c.forward(q), b = urdf.forward(q);
    worst = std::max(worst, positionGap(a, b));
    ASSERT_LT(rotationGap(a, b), 1e-12);
  }
  EXPECT_LT(worst, 1e-9);
  std::cout << "IRB 1600 FK vs independent URDF evaluation: worst " << worst
            << " mm over 505 joint vectors\n";
}

TEST(AbbIrb1600, OpwDetectionRecognisesTheArm)
{
  // From the URDF joint origins: a1 = 150 (joint_2 x), a2 = 0 (axes 3 and 4 at one height), b = 0,
  // c1 = 486.5, c2 = 700, c3 = 300 + 300, c4 = 65; every axis turns with the right-hand rule.
  const OpwDetection d = detectOpw(irb1600());
  ASSERT_TRUE(d.ok) << d.reason;
  const OpwParameters& p = d.model.parameters();
  EXPECT_NEAR(p.a1, 150, 1e-9);
  EXPECT_NEAR(p.a2, 0, 1e-9);
  EXPECT_NEAR(p.b, 0, 1e-9);
  EXPECT_NEAR(p.c1, 486.5, 1e-9);
  EXPECT_NEAR(p.c2, 700, 1e-9);
  EXPECT_NEAR(p.c3, 600, 1e-9);
  EXPECT_NEAR(p.c4, 65, 1e-9);
  EXPECT_EQ(p.signs, (std::array<int, 6>{{1, 1, 1, 1, 1, 1}}));
  // OPW's zero has the forearm upright; the URDF's has it horizontal.
  const std::array<double, 6> offsetsDeg{{0, 0, -90, 0, 0, 0}};
  for (size_t i = 0; i < 6; ++i)
    EXPECT_NEAR(std::remainder(p.offsets[i] - degToRad(offsetsDeg[i]), 2.0 * kPi), 0.0, 1e-12)
        << "offset " << i;
  EXPECT_LT(d.maxPositionError, 1e-9);
}

TEST(AbbIrb1600, InverseThenForwardKinematicsRoundTrips)
{
  const ArmIk ik(irb1600());
  const IndependentUrdf urdf(robotUrdf("abb_irb1600_8_145"));
  std::mt19937 rng(17);
  int found = 0;
  double worst = 0.0;
  for (int k = 0; k < 1000; ++k) {
    const JointVector q = randomWithinLimits(ik.chain(), rng);
    if (ik.dexterity(q) < 1e-3) continue;
    const Transform target = urdf.forward(q);
    bool original = false;
    for (const IkSolution& s : ik.solveAll(target)) {
      const Transform back = urdf.forward(s.q);
      worst = std::max(worst, positionGap(back, target));
      ASSERT_LT(rotationGap(back, target), 1e-9);
      JointVector d = s.q - q;
      for (int i = 0; i < 6; ++i) d[i] = std::remainder(d[i], 2.0 * kPi);
      original = original || d.cwiseAbs().maxCoeff() < 1e-7;
    }
    ASSERT_TRUE(original) << "IK lost the joint vector it came from at sample " << k;
    ++found;
  }
  EXPECT_GT(found, 900);
  EXPECT_LT(worst, 1e-6);
}

TEST(AbbConfData, QuadrantsRoundDown)
{
  EXPECT_EQ(abbQuadrant(0.0), 0);
  EXPECT_EQ(abbQuadrant(89.999), 0);
  EXPECT_EQ(abbQuadrant(90.0), 1);
  EXPECT_EQ(abbQuadrant(-1e-3), -1);
  EXPECT_EQ(abbQuadrant(-5.7e-9), 0);  // IK noise at 0 deg seen along a planned path
  EXPECT_EQ(abbQuadrant(-90.0), -1);
  EXPECT_EQ(abbQuadrant(-90.001), -2);
  EXPECT_EQ(abbQuadrant(359.0), 3);
  EXPECT_EQ(abbQuadrant(-400.0), -5);
  // A value computed as 90 deg from radians lands in the quadrant starting there.
  EXPECT_EQ(abbQuadrant(radToDeg(degToRad(90.0))), 1);
  EXPECT_EQ(abbQuadrant(radToDeg(degToRad(-180.0))), -2);
}

// cfx from the geometry of the independent FK: the wrist centre (the origin of link_5) behind
// axis 1 (negative x in the frame turned by q1), behind the lower arm (on the back side of the
// line from axis 2 to axis 3, seen along +Y of link_1), axis 5 negative.
int geometricCfx(const IndependentUrdf& urdf, const JointVector& q)
{
  const Transform base1 = urdf.forward(q, "link_1");
  const Vec3 wc = base1.inverse() * urdf.forward(q, "link_5").translation();
  const Vec3 axis2 = base1.inverse() * urdf.forward(q, "link_2").translation();
  const Vec3 axis3 = base1.inverse() * urdf.forward(q, "link_3").translation();
  const double side = (axis3 - axis2).cross(wc - axis2).y();
  return (wc.x() < 0.0 ? 4 : 0) | (side < 0.0 ? 2 : 0) | (q[4] < 0.0 ? 1 : 0);
}

TEST(AbbConfData, KnownPosesAndGeometry)
{
  const ArmIk ik(irb1600());
  const ControllerConvention abb(Controller::AbbIrc5, ik.chain());
  EXPECT_EQ(abb.id(), "abb_irc5");
  EXPECT_EQ(abb.axisLimits()[2].name, "rax_3");
  EXPECT_NEAR(abb.axisLimits()[2].minDeg, -245.0, 0.01);  // upstream's -4.27601 rad
  JointPoint p;
  abb.describe(ik.model(), deg(0, 0, 0, 0, 30, 0), p);
  EXPECT_EQ(p.abbConf, (std::array<int, 4>{{0, 0, 0, 0}}));
  EXPECT_NEAR(p.robotDeg[4], 30.0, 1e-12);
  abb.describe(ik.model(), deg(-10, 0, 0, 95, -30, -270), p);
  EXPECT_EQ(p.abbConf, (std::array<int, 4>{{-1, 1, -3, 1}}));
  // Lower arm leaning forward, forearm folded back past the stretched pose (q3 = -90 puts it in line
  // with the lower arm): wrist still in front of axis 1 but behind the lower arm.
  abb.describe(ik.model(), deg(0, 40, -120, 0, 30, 0), p);
  EXPECT_EQ(p.abbConf[3], 2);
  // Leaning back with the forearm pointing up and back: wrist behind axis 1 and behind the arm.
  abb.describe(ik.model(), deg(180, -60, -150, 0, -30, 0), p);
  EXPECT_EQ(p.abbConf, (std::array<int, 4>{{2, 0, 0, 7}}));

  const IndependentUrdf urdf(robotUrdf("abb_irb1600_8_145"));
  std::mt19937 rng(18);
  std::array<int, 8> seen{};
  for (int k = 0; k < 3000; ++k) {
    const JointVector q = randomWithinLimits(ik.chain(), rng);
    if (ik.dexterity(q) < 1e-3) continue;
    const AbbConfData c = abbConfData(ik.model(), q);
    ASSERT_EQ(c.values[3], geometricCfx(urdf, q)) << "sample " << k;
    ASSERT_EQ(c.values[0], static_cast<int>(std::floor(radToDeg(q[0]) / 90.0)));
    ++seen[static_cast<size_t>(c.values[3])];
  }
  for (size_t cfx = 0; cfx < 8; ++cfx) EXPECT_GT(seen[cfx], 0) << "cfx " << cfx << " never drawn";
}

}  // namespace
}  // namespace spira
