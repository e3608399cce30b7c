#pragma once

#include <limits>
#include <string>
#include <vector>

namespace spira {

// The spin of one layer of a solved motion.
struct LayerSpin {
  int path = 0;
  int revolution = 0;
  size_t firstPoint = 0;
  size_t pointCount = 0;
  // The chart spin polynomial a_0..a_n (rad) over the layer's abscissa (spin_optimiser.h); one
  // value for the constant spin held in the robot frame; empty for the travel-relative spin.
  std::vector<double> coefficients;
  double startSpinRad = 0.0;  // tool_frame.h spin at the layer's first point
  double endSpinRad = 0.0;    // ... at its last point
  double objective = 0.0;     // Phi (see below) of its segments, the one into the next layer included
  bool polished = false;      // the optimiser re-solved it on every point after the subsample search
};

// What a motion solve found, per point and overall. Angles in the controller's degrees, point
// indices into the path. "Reached" means the inverse kinematics reaches the pose in the path's
// configuration and the positioner (if any) turns the build direction vertical.
struct MotionReport {
  static constexpr size_t kNone = std::numeric_limits<size_t>::max();

  bool reachable = true;              // every point reached with every axis inside its limits
  std::vector<size_t> unreachable;    // points not reached (their joints repeat the previous point's)
  std::vector<size_t> outsideLimits;  // reached, but a robot or positioner axis is beyond its limit

  // Over reached points: the smallest distance of any axis to its limits (negative outside).
  double minLimitMarginDeg = std::numeric_limits<double>::infinity();
  std::string minLimitMarginAxis;  // "A5", "J3", "E2" ...
  size_t minLimitMarginPoint = kNone;
  double minDexterity = 1.0;  // dexterity.h
  size_t minDexterityPoint = kNone;
  // Largest |dA/dt| / max speed over axes (robot and positioner) and segments between reached
  // points, dt = segment length (part frame) / travel speed of its end point. Above 1 the
  // travel speed must drop there. Segments whose end point has no travel speed are skipped.
  double maxSpeedRatio = 0.0;
  std::string maxSpeedRatioAxis;
  size_t maxSpeedRatioPoint = kNone;  // the segment's end point
  size_t segmentsWithoutSpeed = 0;
  // Per point, the largest of those ratios over the axes on the segment into it (0 where there is
  // none: the first point, a segment from or to an unreached point, no travel speed).
  std::vector<double> speedRatio;
  // Per axis (robot axes, then the positioner's), its largest ratio and where.
  struct AxisSpeed {
    std::string axis;
    double maxRatio = 0.0;
    size_t point = kNone;
  };
  std::vector<AxisSpeed> axisSpeeds;
  // Torch cable twist |q4 + q6| (controller degrees) over reached points, and its limit check
  // (always true when the limit is 0 = off).
  double maxCableTwistDeg = 0.0;
  size_t maxCableTwistPoint = kNone;
  bool withinCableTwistLimit = true;

  // Phi = sum over segments of sum_j (dA_j)^2 / range_j (robot axes, deg) and the constraint
  // penalty (spin_cost.h) of the constant-spin plan and of the returned plan.
  double objectiveConstant = 0.0;
  double penaltyConstant = 0.0;
  double objectiveResult = 0.0;
  double penaltyResult = 0.0;
  bool optimised =
      false;            // the returned plan is the optimised one (false: off, or the constant one cost less)
  int posesSolved = 0;  // inverse kinematics solves spent by the optimiser
  std::vector<LayerSpin> layers;
};

}  // namespace spira
