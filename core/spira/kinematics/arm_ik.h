#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "spira/kinematics/ik_solution.h"
#include "spira/kinematics/kinematic_chain.h"
#include "spira/kinematics/opw_model.h"

namespace spira {

// Inverse kinematics of a 6R arm with a spherical wrist and an ortho-parallel base, for any chain
// of that form (no robot is hard-coded): the OPW form is derived from the chain (opw_detection.h),
// solved in closed form, then refined by Newton steps on the chain itself until the tip is within
// 1e-10 mm and 1e-13 rad of the target (tip = the chain's tip link, e.g. tool0; poses are T_base_tip).
// Solutions carry their errors, so a caller can tell a pose the chain cannot quite reach.
class ArmIk {
 public:
  // Throws InputError (with the reason) when the chain is not a 6R arm of that form.
  explicit ArmIk(KinematicChain chain);

  const KinematicChain& chain() const { return chain_; }
  const OpwModel& model() const { return model_; }

  // Which limits solutions are flagged against: per-axis distances to the limits (rad, negative
  // outside). Default: the chain's joint boxes. A controller may limit an axis relative to another
  // (FANUC J3 relative to J2): see ControllerConvention::applyTo.
  using AxisMargins = std::function<JointVector(const JointVector&)>;
  void setAxisMargins(AxisMargins margins);
  JointVector axisMargins(const JointVector& q) const;
  double limitMargin(const JointVector& q) const { return axisMargins(q).minCoeff(); }

  Transform forward(const JointVector& q) const { return chain_.forward(q); }
  ArmConfiguration configurationOf(const JointVector& q) const { return model_.configurationOf(q); }
  // The wrist centre (intersection of axes 4-6) in the base frame.
  Vec3 wristCentre(const JointVector& q) const;
  // Dexterity at q, see dexterity.h.
  double dexterity(const JointVector& q) const;

  // Every solution: one per reachable configuration (index order), each joint in (-pi, pi] or,
  // if that is outside its limits and a 2 pi shift is less so, the shifted value; then, for
  // joints 1, 4 and 6, the same solution shifted by +-2 pi wherever the shifted value is within
  // its limits. Solutions outside the limits are kept and flagged.
  std::vector<IkSolution> solveAll(const Transform& baseTip) const;
  // The solution of one configuration, each joint on the 2 pi branch nearest `near` (also the
  // hint at a wrist singularity), or nothing when out of reach for that configuration.
  std::optional<IkSolution> solve(const Transform& baseTip, const ArmConfiguration& configuration,
                                  const JointVector& near) const;

  // Newton steps on the chain from q towards the target; true when converged.
  bool refine(const Transform& baseTip, JointVector& q) const;

 private:
  bool solveBranch(const Transform& baseTip, const ArmConfiguration& configuration, double theta4Hint,
                   JointVector& q) const;
  // Newton steps on s.q, then the errors, dexterity and limit margin at the result.
  bool refineAndMeasure(const Transform& baseTip, IkSolution& s) const;

  KinematicChain chain_;
  OpwModel model_;
  AxisMargins axisMargins_;
};

}  // namespace spira
