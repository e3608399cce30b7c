#include "spira/kinematics/kuka_status_turn.h"

#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"

namespace spira {

KukaStatusTurn kukaStatusTurn(const OpwModel& model, const JointVector& q)
{
  const JointVector theta = model.toOpw(q);
  KukaStatusTurn st;
  if (model.wristReach(theta) < 0.0) st.status |= 1;
  if (wrapToPi(q[2] - model.stretchedJoint3()) >= 0.0) st.status |= 2;
  const double a5 = radToDeg(q[4]);
  if (a5 >= 180.0 || (a5 >= -180.0 && a5 < 0.0)) st.status |= 4;
  for (int i = 0; i < 6; ++i)
    if (q[i] < 0.0) st.turn |= 1 << i;
  return st;
}

std::optional<JointVector> kukaJointsFrom(const ArmIk& ik, const Transform& baseTip, int status, int turn)
{
  for (const IkSolution& s : ik.solveAll(baseTip)) {
    if (!s.withinLimits) continue;
    const KukaStatusTurn st = kukaStatusTurn(ik.model(), s.q);
    if (st.status == (status & 7) && st.turn == (turn & 63)) return s.q;
  }
  return std::nullopt;
}

}  // namespace spira
