#include "spira/kinematics/controller_convention.h"

#include <algorithm>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/kinematics/abb_confdata.h"
#include "spira/kinematics/fanuc_config.h"
#include "spira/kinematics/kuka_status_turn.h"

namespace spira {

ControllerConvention::ControllerConvention(Controller controller, const KinematicChain& chain)
    : controller_(controller)
{
  if (chain.size() != 6)
    throw InputError("a controller convention needs a 6-joint arm; the chain " + chain.baseLink() + " -> " +
                         chain.tipLink() + " has " + std::to_string(chain.size()),
                     "choose the arm's chain from its foot to its flange or tool0 link");
  const std::string prefix = controller == Controller::KukaKrc4     ? "A"
                             : controller == Controller::FanucR30ib ? "J"
                                                                    : "rax_";
  for (size_t i = 0; i < 6; ++i) {
    const ChainJoint& j = chain.joint(i);
    AxisLimit& l = limits_[i];
    l.name = prefix + std::to_string(i + 1);
    l.minDeg = radToDeg(j.lower);
    l.maxDeg = radToDeg(j.upper);
    l.maxSpeedDegPerS = radToDeg(j.maxVelocity);
  }
}

std::string ControllerConvention::id(Controller controller)
{
  switch (controller) {
    case Controller::KukaKrc4:
      return "kuka_krc4";
    case Controller::FanucR30ib:
      return "fanuc_r30ib";
    case Controller::AbbIrc5:
      return "abb_irc5";
  }
  return "unknown";
}

Controller ControllerConvention::parse(const std::string& id)
{
  if (id == "kuka_krc4") return Controller::KukaKrc4;
  if (id == "fanuc_r30ib") return Controller::FanucR30ib;
  if (id == "abb_irc5") return Controller::AbbIrc5;
  throw InputError("unknown robot controller '" + id + "'", "use kuka_krc4, fanuc_r30ib or abb_irc5");
}

std::array<double, 6> ControllerConvention::toControllerDeg(const JointVector& q) const
{
  std::array<double, 6> deg;
  for (int i = 0; i < 6; ++i) deg[static_cast<size_t>(i)] = radToDeg(q[i]);
  if (controller_ == Controller::FanucR30ib) deg[2] = radToDeg(q[2] - q[1]);
  return deg;
}

JointVector ControllerConvention::fromControllerDeg(const std::array<double, 6>& deg) const
{
  JointVector q;
  for (int i = 0; i < 6; ++i) q[i] = degToRad(deg[static_cast<size_t>(i)]);
  if (controller_ == Controller::FanucR30ib) q[2] = degToRad(deg[2] + deg[1]);
  return q;
}

JointVector ControllerConvention::axisMargins(const JointVector& q) const
{
  const std::array<double, 6> deg = toControllerDeg(q);
  JointVector m;
  for (size_t i = 0; i < 6; ++i)
    m[static_cast<Eigen::Index>(i)] =
        degToRad(std::min(deg[i] - limits_[i].minDeg, limits_[i].maxDeg - deg[i]));
  return m;
}

void ControllerConvention::applyTo(ArmIk& ik) const
{
  const ControllerConvention self = *this;
  ik.setAxisMargins([self](const JointVector& q) { return self.axisMargins(q); });
}

void ControllerConvention::describe(const OpwModel& model, const JointVector& q, JointPoint& point) const
{
  point.robotDeg = toControllerDeg(q);
  if (controller_ == Controller::KukaKrc4) {
    const KukaStatusTurn st = kukaStatusTurn(model, q);
    point.kukaStatus = st.status;
    point.kukaTurn = st.turn;
  } else if (controller_ == Controller::FanucR30ib) {
    point.fanucConfig = fanucConfig(model, q).format();
  } else {
    point.abbConf = abbConfData(model, q).values;
  }
}

}  // namespace spira
