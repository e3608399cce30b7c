#pragma once

#include "spira/base/transform.h"

namespace spira {

// What "constant spin" means when the optimisation is off (and for the comparison plan).
enum class ConstantSpin {
  // The torch keeps its turn about its own axis fixed in the robot base frame (Chalvin's R_Z held
  // constant, Eq. 3.12-3.13): the spin chart of motion_frames.h at a constant value. Its value is
  // set by JointPathSetup::spinRad at the first point (tool_frame.h convention).
  InRobotFrame,
  // JointPathSetup::spinRad at every point (tool_frame.h: torch x follows the travel direction),
  // exactly what solveJointTrajectory does. The torch turns once per revolution about its axis,
  // so on a robot-only cell the wrist winds up by a turn per layer.
  RelativeToTravel
};

// The abscissa x of the spin polynomial of a layer (Chalvin Eq. 4.1-4.2).
enum class SpinVariable {
  PointIndex,  // x = m / p_C for point m of a layer of p_C points (0 at its first point, 1 at the next
               // layer's)
  PolarAngle   // x = (theta_m - theta_0) / 2 pi, theta the unwrapped angle about `axis` (parts of revolution)
};

// Parameters of the motion solve (spin optimisation and per-point checks). Units as named.
struct MotionParams {
  // Optimise the spin about the torch axis layer by layer (Chalvin ch. 4). Off: constant spin.
  bool optimiseSpin = true;
  ConstantSpin constantSpin = ConstantSpin::InRobotFrame;
  // Degree n of the spin polynomial of each layer, 0..6 (Chalvin found n = 1 to 3 enough).
  int degree = 3;
  SpinVariable variable = SpinVariable::PointIndex;
  // The axis of revolution for SpinVariable::PolarAngle, in the part frame (mm, unit direction).
  Vec3 axisPoint = Vec3::Zero();
  Vec3 axisDirection = Vec3::UnitZ();
  // Dexterity (dexterity.h, 0 at a singularity, 1 at best) the optimiser keeps every point above.
  // tan(A5 / 2) for the wrist block, so 0.05 keeps the wrist about 5.7 deg from its singularity.
  double dexterityFloor = 0.05;
  // |q4 + q6| in controller degrees (torch cable bundle twist, Chalvin Eq. 4.8); 0 = no limit.
  // Take it from the cell (cable_twist_limit_deg).
  double cableTwistLimitDeg = 0.0;
  // Distance (deg) the optimiser keeps every robot axis from its controller limits.
  double limitMarginDeg = 2.0;
  // Weight of the centring term against the joint motion of a layer (spin_cost.h): the layer's
  // mean of sum_j ((A_j - mid_j) / half range_j)^2 + (twist / twist limit)^2. Each layer starts
  // where the previous one ended, so a spin that drifts towards a limit over many layers would
  // only meet it when no later layer can get away; a small pull to mid-range prevents that.
  // 0 = pure joint motion (Chalvin Eq. 4.3).
  double centringWeight = 0.01;
  // Levenberg-Marquardt iterations per layer (search on a subsample; the polish on the full layer
  // gets a quarter of them).
  int maxIterations = 40;
  // Points of a layer the search evaluates (evenly spaced, first and last included); the result
  // is then evaluated, and polished if it breaks a constraint, on every point of the layer.
  int searchSamples = 36;
  // With a positioner, a build direction along the rotation axis leaves the rotation free
  // (vertical walls on a turntable). On: the rotation follows the point so that it stays where
  // the previous one was (the table turns the part under the torch). Off: the rotation is held,
  // as solveJointTrajectory does, and the robot travels around the part. Either way this is the
  // target the rotation keeps to wherever the tolerance below allows.
  bool turntableFollowsPoint = true;
  // Angle (deg) from the vertical the positioner may leave a build direction at. Within it of the
  // rotation axis the rotation is free; beyond, the rotation may stray from the exact solution as
  // far as keeps the direction within it. A spiral's build direction leans by its climb per turn,
  // atan(h / (2 pi r)) (0.9 deg for h = 2 mm at r = 20 mm), and by facet noise: with an exact
  // solution that lean's azimuth drives the rotation, which then jumps by up to 90 deg between
  // points. Welding's flat position (ISO 6947 PA) allows far more than 2 deg.
  double buildTiltToleranceDeg = 2.0;

  // Throws InputError naming the bad field.
  void validate() const;
};

}  // namespace spira
