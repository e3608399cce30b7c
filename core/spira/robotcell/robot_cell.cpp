#include "spira/robotcell/robot_cell.h"

#include <urdf_parser/urdf_parser.h>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/kinematics/urdf_parse.h"
#include "spira/path/tool_frame.h"

namespace spira {

namespace {

Controller controllerOf(ControllerFamily family)
{
  switch (family) {
    case ControllerFamily::KukaKrc4:
      return Controller::KukaKrc4;
    case ControllerFamily::FanucR30iB:
      return Controller::FanucR30ib;
    case ControllerFamily::AbbIrc5:
      return Controller::AbbIrc5;
  }
  return Controller::KukaKrc4;
}

std::string rootLinkOf(const std::string& urdfPath)
{
  return parseUrdfModel(readFile(urdfPath), "the robot description " + urdfPath)->getRoot()->name;
}

// T_root_link: the fixed joints from the URDF root down to `link` (none of them may move).
Transform rootToLink(const std::string& urdfPath, const std::string& link)
{
  const std::string root = rootLinkOf(urdfPath);
  if (root == link) return Transform::Identity();
  const KinematicChain c = KinematicChain::fromUrdfFile(urdfPath, root, link);
  if (c.size() != 0)
    throw InputError("the link " + link + " of " + urdfPath + " moves with a joint of the robot",
                     "set the cell's base_link to a link fixed to the robot's foot");
  return c.forward(Eigen::VectorXd());
}

// The chain with the controller limits of the cell's axes, in controller order.
KinematicChain withCellAxes(const KinematicChain& chain, const std::vector<CellAxis>& axes,
                            const std::string& what)
{
  if (axes.size() != chain.size())
    throw InputError(what + ": the cell maps " + std::to_string(axes.size()) + " axes but the chain " +
                         chain.baseLink() + " -> " + chain.tipLink() + " has " +
                         std::to_string(chain.size()) + " joints",
                     "list one axis per joint, in controller order");
  std::vector<ChainJoint> joints = chain.joints();
  for (size_t i = 0; i < axes.size(); ++i) {
    const CellAxis& a = axes[i];
    if (a.urdfJoint != joints[i].name)
      throw InputError(what + " axis " + std::to_string(i + 1) + " names joint '" + a.urdfJoint +
                           "', but joint " + std::to_string(i + 1) + " of the chain is '" + joints[i].name +
                           "'",
                       "list the axes in the chain's order");
    if (a.sign != 1 || a.offsetDeg != 0.0)
      throw InputError(what + " axis " + std::to_string(i + 1) + " has sign " + std::to_string(a.sign) +
                           " and offset " + std::to_string(a.offsetDeg) +
                           " deg; this version supports the controllers' own URDF conventions only",
                       "use a URDF whose joint senses and zeros are the controller's (see "
                       "resources/robots/README.md) with sign 1 and offset 0");
    joints[i].lower = degToRad(a.minDeg);
    joints[i].upper = degToRad(a.maxDeg);
    joints[i].maxVelocity = degToRad(a.maxSpeedDegPerS);
  }
  return KinematicChain(chain.baseLink(), chain.tipLink(), std::move(joints), chain.tipOffset());
}

}  // namespace

RobotCell::RobotCell(const CellRecord& record) : record_(record)
{
  const std::string armWhat = "robot of cell '" + record.name + "'";
  arm_ = std::make_unique<KinematicChain>(
      withCellAxes(KinematicChain::fromUrdfFile(record.robotUrdf, record.robotBaseLink, record.robotTipLink),
                   record.robotAxes, armWhat));
  if (record.controller == ControllerFamily::FanucR30iB && record.j23Coupling != 1)
    throw InputError(armWhat + ": FANUC cells need j23_coupling 1 (the J2/J3 linkage of the R-30iB arms)",
                     "set robot.j23_coupling to 1");
  if (record.controller == ControllerFamily::KukaKrc4 && record.j23Coupling != 0)
    throw InputError(armWhat + ": KUKA arms have no J2/J3 linkage", "set robot.j23_coupling to 0");
  if (record.controller == ControllerFamily::AbbIrc5 && record.j23Coupling != 0)
    throw InputError(
        armWhat + ": Spira supports ABB's serial arms (IRB 1600, 2600...), without a J2/J3 linkage",
        "set robot.j23_coupling to 0 and use a serial arm");
  convention_ = std::make_unique<ControllerConvention>(controllerOf(record.controller), *arm_);
  try {
    ik_ = std::make_unique<ArmIk>(*arm_);
    convention_->applyTo(*ik_);
  } catch (const InputError& e) {
    ikRefusal_ = e.what();
  }
  T_world_base_ = record.T_world_robotbase * rootToLink(record.robotUrdf, record.robotBaseLink);

  if (record.hasPositioner()) {
    const std::string posWhat = "positioner of cell '" + record.name + "'";
    positioner_ = std::make_unique<TiltRotatePositioner>(
        withCellAxes(KinematicChain::fromUrdfFile(record.positionerUrdf, record.positionerBaseLink,
                                                  record.positionerTipLink),
                     record.positionerAxes, posWhat));
    const Transform worldPositioner =
        record.T_world_positioner * rootToLink(record.positionerUrdf, record.positionerBaseLink);
    T_base_positioner_ = T_world_base_.inverse() * worldPositioner;
  }
}

const ArmIk& RobotCell::ik() const
{
  if (!ik_)
    throw InputError("cell '" + record_.name + "' cannot solve joint motion: " + ikRefusal_,
                     "use a 6-axis arm with a spherical wrist (all bundled robots are)");
  return *ik_;
}

JointPathSetup RobotCell::setup(const std::optional<Transform>& worldPart) const
{
  JointPathSetup s;
  s.cellName = record_.name;
  s.flangeTcp = record_.tool.T_flange_tcp;
  if (positioner_ && record_.mounting == PartMounting::Positioner) {
    s.positioner = positioner_.get();
    s.basePositioner = T_base_positioner_;
    s.tablePart = record_.T_mount_part;
  } else {
    s.basePart = T_world_base_.inverse() * worldPart.value_or(record_.T_mount_part);
  }
  return s;
}

JointPathSetup RobotCell::seededSetup(const Trajectory& path, const std::optional<Transform>& worldPart) const
{
  JointPathSetup s = setup(worldPart);
  if (path.empty() || !ik_) return s;
  const TrajectoryPoint& first = path.points.front();
  Transform basePart = s.basePart;
  if (s.positioner) {
    const auto e = s.positioner->solve(s.tablePart.linear() * first.build, s.positionerSeed);
    if (!e) return s;
    s.positionerSeed = *e;
    basePart = s.basePositioner * s.positioner->forward(*e) * s.tablePart;
  }
  const auto solutions = ik_->solveAll(basePart * toolFrame(first, s.spinRad) * s.flangeTcp.inverse());
  if (solutions.empty()) return s;
  const IkSolution* best = &solutions.front();
  for (const IkSolution& sol : solutions)
    if (sol.limitMargin > best->limitMargin) best = &sol;
  s.seed = best->q;
  s.configuration = best->configuration;
  return s;
}

}  // namespace spira
