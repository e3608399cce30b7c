#pragma once

#include <array>

#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/controller_convention.h"
#include "spira/motion/motion_frames.h"
#include "spira/motion/motion_params.h"

namespace spira {

// One point solved at some spin: URDF joints and the controller's axes.
struct SolvedPose {
  JointVector q = JointVector::Zero();  // the near joint vector when not reached
  std::array<double, 6> deg{};          // controller axes (ControllerConvention::toControllerDeg)
  bool reached = false;                 // within 1e-6 mm and 1e-8 rad, as trackPath decides
  double dexterity = 0.0;
};

// The joint-space cost of a choice of spins (Chalvin Eq. 4.3-4.8), as least-squares residuals.
// Objective: Phi = sum over path segments of sum_j w_j (dA_j)^2, controller axes in degrees,
// w_j = 1 / range_j (deg), robot axes only (the positioner does not depend on the spin).
// Constraints become penalties, mu * excess^2 with excess in degrees (mu = kPenaltyWeight):
//   each axis at least params.limitMarginDeg inside its controller limits;
//   dexterity >= params.dexterityFloor (its deficit counted as kDexterityDegrees deg per unit);
//   |A4 + A6| <= params.cableTwistLimitDeg when that is > 0;
//   an unreachable pose costs kUnreachableResidual^2.
// Each hinge starts kSlackDeg (kSlackDexterity) inside its bound: a quadratic penalty settles a
// little beyond where it starts, and that must still be inside the bound.
// Centring (params.centringWeight): the mean over a layer of sum_j ((A_j - mid_j) / half range_j)^2
// plus (twist / twist limit)^2, times the weight (Chalvin's joint centring, Eq. 1.4, kept small).
class SpinCost {
 public:
  // Residual layout per point: objective, penalties, centring.
  static constexpr int kObjective = 0;
  static constexpr int kPenalty = 6;    // 6 limits, dexterity, twist, reach
  static constexpr int kCentring = 15;  // 6 axes, twist
  static constexpr int kResidualsPerPoint = 22;
  static constexpr double kPenaltyWeight = 1e4;
  static constexpr double kDexterityDegrees = 100.0;
  static constexpr double kUnreachableResidual = 1e4;
  static constexpr double kSlackDeg = 0.01;
  static constexpr double kSlackDexterity = 1e-4;

  SpinCost(const ArmIk& ik, const ControllerConvention& convention, const MotionFrames& frames,
           const Transform& flangeTcp, const ArmConfiguration& configuration, const MotionParams& params);

  // Point `index` at chart spin value `chartSpin` (motion_frames.h), each joint on the 2 pi branch
  // nearest `near`.
  SolvedPose solve(size_t index, double chartSpin, const JointVector& near) const;
  // T_base_tcp of point `index` at tool_frame.h spin `toolSpin`.
  Transform baseTcp(size_t index, double toolSpin) const;

  // Writes kResidualsPerPoint residuals for `pose` reached from `previous` over `segments` path
  // segments (no previous: the objective part is zero). With a subsample, a step over k segments
  // stands for k steps of 1/k of it: sum_k w (d/k)^2 = w d^2 / k. `share`: this point's share of
  // its layer's mean (k / points in the layer), for the centring.
  void residuals(const SolvedPose* previous, double segments, const SolvedPose& pose, double share,
                 double* out) const;
  // The objective part only: sum_j w_j (b_j - a_j)^2.
  double objective(const SolvedPose& a, const SolvedPose& b) const;
  // The penalty part only, for one pose.
  double penalty(const SolvedPose& pose) const;

  const std::array<double, 6>& weights() const { return weights_; }
  const ArmIk& ik() const { return ik_; }
  const ControllerConvention& convention() const { return convention_; }
  const MotionFrames& frames() const { return frames_; }
  const ArmConfiguration& configuration() const { return configuration_; }
  const MotionParams& params() const { return params_; }

 private:
  const ArmIk& ik_;
  const ControllerConvention& convention_;
  const MotionFrames& frames_;
  Transform tcpFlange_;
  ArmConfiguration configuration_;
  const MotionParams& params_;
  std::array<double, 6> weights_{};
  std::array<double, 6> mid_{}, halfRange_{};
};

}  // namespace spira
