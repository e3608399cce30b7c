#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "gcode_machine.h"
#include "spira/base/transform.h"

namespace spira {

// The machine's axis values at one pose: linear mm (machine coordinates), rotary deg in file order.
struct HeadAxes {
  Vec3 linear = Vec3::Zero();
  std::array<double, 2> rotaryDeg{};
};

// Where the head puts the tool: tip in machine coordinates (mm) and the unit torch axis.
struct HeadPose {
  Vec3 tip = Vec3::Zero();
  Vec3 axis = -Vec3::UnitZ();
};

// The head's forward kinematics:
//   tip  = linear + R1 (firstToSecond + R2 secondToTip),  axis = R1 R2 toolDirection,
// R1 and R2 turning about the rotary axes' directions by their angles (right hand).
HeadPose headForward(const GcodeMachine& m, const HeadAxes& axes);

// The rotary angles (deg, each in (-180, 180]) that turn the torch along `axis` (unit): none when the
// head cannot point that way, else one or two branches. Where the first rotary angle is free (the
// axis along the first rotary axis) it is `freeFirstDeg`.
std::vector<std::array<double, 2>> headOrientations(const GcodeMachine& m, const Vec3& axis,
                                                    double freeFirstDeg);

// The linear axes that put the tip at `tip` (machine coordinates) with the rotary angles given.
Vec3 headLinear(const GcodeMachine& m, const Vec3& tip, const std::array<double, 2>& rotaryDeg);

// Axis values for a sequence of poses in the part frame (tip and torch axis; the part frame is the
// machine's shifted to m.partOrigin): per pose the branch and the turn of each rotary axis (multiples
// of 360 deg) nearest the previous pose's, within the limits, so the head never flips and a rotary
// axis turning round keeps counting (unwrapped). Throws InputError naming the pose (`poseName` of
// its position in the list) and the axis when no solution lies within the limits. A torch axis within
// `uprightToleranceDeg` of the head's zero direction is taken as that direction (the first rotary
// axis then keeps its angle): a spiral's slight lean would otherwise turn it once per revolution.
std::vector<HeadAxes> solveHeadPath(const GcodeMachine& m, const std::vector<HeadPose>& poses,
                                    const std::function<std::string(size_t)>& poseName,
                                    double uprightToleranceDeg = 0.0);

}  // namespace spira
