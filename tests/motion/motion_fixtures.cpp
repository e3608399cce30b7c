#include "motion_fixtures.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "spira/base/units.h"
#include "spira/path/tool_frame.h"
#include "support/test_support.h"

namespace spira::test {

std::string motionRobotUrdf(const std::string& name)
{
  const std::filesystem::path p = sourceDir() / "resources" / "robots" / name / "robot.urdf";
  if (!std::filesystem::exists(p)) throw std::runtime_error("missing robot description " + p.string());
  return p.string();
}

Transform translation(double x, double y, double z)
{
  Transform t = Transform::Identity();
  t.translation() = Vec3(x, y, z);
  return t;
}

KukaCell::KukaCell()
    : ik(KinematicChain::fromUrdfFile(motionRobotUrdf("kuka_kr16_2"), "base_link", "tool0")),
      convention(Controller::KukaKrc4, ik.chain())
{
  convention.applyTo(ik);
  setup.cellName = "KUKA KR 16-2 on a fixed table";
  setup.basePart = translation(1100, 0, 400);
  setup.flangeTcp = translation(0, 0, 350);
}

void KukaCell::seedAt(const Trajectory& path)
{
  const Transform tip =
      setup.basePart * toolFrame(path.points.front(), setup.spinRad) * setup.flangeTcp.inverse();
  const std::optional<IkSolution> s = ik.solve(tip, ArmConfiguration{}, JointVector::Zero());
  if (!s) throw std::runtime_error("KUKA cell: first point out of reach");
  setup.seed = s->q;
}

namespace {

KinematicChain endlessPositioner()
{
  const KinematicChain read =
      KinematicChain::fromUrdfFile(motionRobotUrdf("positioner_2axis"), "base_link", "table_top");
  std::vector<ChainJoint> joints = read.joints();
  joints[1].lower = degToRad(-36000.0);
  joints[1].upper = degToRad(36000.0);
  return KinematicChain(read.baseLink(), read.tipLink(), joints, read.tipOffset());
}

}  // namespace

FanucPositionerCell::FanucPositionerCell()
    : ik(KinematicChain::fromUrdfFile(motionRobotUrdf("fanuc_m20ia"), "base", "tool0")),
      convention(Controller::FanucR30ib, ik.chain()),
      positioner(std::make_unique<TiltRotatePositioner>(endlessPositioner()))
{
  convention.applyTo(ik);
  setup.cellName = "FANUC M-20iA with a 2-axis positioner";
  setup.positioner = positioner.get();
  setup.basePositioner = translation(1100, 0, -525);
  setup.tablePart = Transform::Identity();
  setup.flangeTcp = translation(0, 0, 350);
}

void FanucPositionerCell::seedAt(const Trajectory& path)
{
  Transform tcp = Transform::Identity();
  tcp.linear() = Eigen::AngleAxisd(kPi, Vec3::UnitX()).toRotationMatrix();
  const Transform table = setup.basePositioner * positioner->forward(setup.positionerSeed) * setup.tablePart;
  tcp.translation() = table * path.points.front().position;
  const std::optional<IkSolution> s =
      ik.solve(tcp * setup.flangeTcp.inverse(), ArmConfiguration{}, JointVector::Zero());
  if (!s) throw std::runtime_error("FANUC cell: first point out of reach");
  setup.seed = s->q;
}

Trajectory stackedCircles(double r, int layers, int perLayer, double z0, double dz, double speed)
{
  Trajectory path;
  for (int k = 0; k < layers; ++k)
    for (int m = 0; m < perLayer; ++m) {
      const double a = 2 * kPi * m / perLayer;
      TrajectoryPoint p;
      p.position = Vec3(r * std::cos(a), r * std::sin(a), z0 + k * dz);
      p.normal = Vec3(std::cos(a), std::sin(a), 0);
      p.tangent = Vec3(-std::sin(a), std::cos(a), 0);
      p.build = p.normal.cross(p.tangent);
      p.revolution = k;
      p.travelSpeed = speed;
      path.points.push_back(p);
    }
  return path;
}

Trajectory domeSpiral(double r, double polarEndDeg, int turns, int perTurn, double speed)
{
  Trajectory path;
  const int n = turns * perTurn;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / perTurn;
    const double polar = degToRad(90.0 - (90.0 - polarEndDeg) * k / n);
    TrajectoryPoint p;
    p.normal = Vec3(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    p.position = r * p.normal;
    p.tangent = Vec3(-std::sin(a), std::cos(a), 0);
    p.build = p.normal.cross(p.tangent);
    p.revolution = k / perTurn;
    p.travelSpeed = speed;
    path.points.push_back(p);
  }
  return path;
}

}  // namespace spira::test
