#pragma once

#include <array>
#include <optional>

#include <Eigen/Core>

#include "spira/base/transform.h"
#include "spira/kinematics/kinematic_chain.h"

namespace spira {

// A 2-axis positioner (e.g. positioner_2axis: E1 tilt about Y, E2 rotate about the table normal)
// read from a 2-joint chain from its base to its table frame. Axis values are URDF radians.
//
// Its inverse kinematics is the flat-position problem of welding (Chalvin, 004_bd0df31205c0c3c0.txt Appendix
// C.2.3, Eq. C.24-C.25): turn a direction given in the table frame (the part's build direction b) to the
// vertical of the positioner base. For positioner_2axis, R_base_table = Ry(e1) Rz(e2), and the thesis' closed
// form
//   e1 = atan2(sqrt(bx^2 + by^2), bz),  e2 = atan2(by, -bx)
// (the printed R_X, R_Y, R_Z are b's components; docs/method.md M22) is one of the two
// solutions. Here it is solved for any two non-parallel axes (Paden-Kahan subproblem 2 on the
// chain's axes at zero), so the other branch (-e1, e2 + pi) and 2 pi turns of the rotation come out
// too and the one nearest the previous axis values is taken.
class TiltRotatePositioner {
 public:
  using Axes = Eigen::Vector2d;

  // Throws InputError unless the chain has exactly 2 revolute joints with non-parallel axes.
  explicit TiltRotatePositioner(KinematicChain chain);

  const KinematicChain& chain() const { return chain_; }
  // T_positionerBase_table.
  Transform forward(const Axes& e) const { return chain_.forward(e); }
  double limitMargin(const Axes& e) const { return chain_.limitMargin(e); }

  // Both solutions (tilt branch first with e1 >= 0) that turn `directionInTable` onto `up`
  // (positioner base frame, default +Z), each wrapped to (-pi, pi]; empty if no rotation of these
  // two axes can do it. When the direction is already along the rotation axis, e2 is free and
  // `freeRotation` is used.
  std::vector<Axes> solveAll(const Vec3& directionInTable, const Vec3& up = Vec3::UnitZ(),
                             double freeRotation = 0.0) const;
  // The solution nearest `previous` (each axis on its 2 pi branch nearest previous), or nothing.
  std::optional<Axes> solve(const Vec3& directionInTable, const Axes& previous,
                            const Vec3& up = Vec3::UnitZ()) const;

  // Axes that turn `directionInTable` to within `tolerance` (rad, >= 0) of `up`, the rotation (axis
  // 2) as near `rotation` as that allows, on its 2 pi branch, and the tilt (axis 1) the one that
  // then brings the direction closest to `up`, on the 2 pi branch nearest `previousTilt`; nothing
  // when no rotation brings it within the tolerance. With tolerance 0 this is an exact solution.
  // Why a tolerance: a direction within it of the rotation axis leaves the rotation free, and just
  // outside it the exact rotation follows the direction's azimuth about the axis, which a small
  // tilt (a helix's climb, facet noise) leaves ill-defined; the set of rotations that keep the
  // direction within the tolerance shrinks continuously instead, so the rotation can stay near a
  // smooth target.
  std::optional<Axes> solveWithin(const Vec3& directionInTable, double tolerance, double rotation,
                                  double previousTilt, const Vec3& up = Vec3::UnitZ()) const;

 private:
  KinematicChain chain_;
  Vec3 axis1_, axis2_;  // base frame, zero pose
  Mat3 tableAtZero_;    // R_base_table at e = 0
};

}  // namespace spira
