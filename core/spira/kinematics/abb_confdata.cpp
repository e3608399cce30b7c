#include "spira/kinematics/abb_confdata.h"

#include <cmath>

#include "spira/base/units.h"

namespace spira {

namespace {
// Solver noise around 0 deg (1e-9 deg and less) must not flip a quadrant from one point to the next.
constexpr double kQuadrantSnapDeg = 1e-6;
}  // namespace

std::string AbbConfData::format() const
{
  return "[" + std::to_string(values[0]) + "," + std::to_string(values[1]) + "," + std::to_string(values[2]) +
         "," + std::to_string(values[3]) + "]";
}

int abbQuadrant(double deg)
{
  return static_cast<int>(std::floor((deg + kQuadrantSnapDeg) / 90.0));
}

AbbConfData abbConfData(const OpwModel& model, const JointVector& q)
{
  const JointVector theta = model.toOpw(q);
  const bool behindAxis1 = model.wristReach(theta) < 0.0;
  const bool behindLowerArm = model.elbowAngle(theta) < 0.0;
  const bool axis5Negative = q[4] < 0.0;
  AbbConfData c;
  c.values = {abbQuadrant(radToDeg(q[0])), abbQuadrant(radToDeg(q[3])), abbQuadrant(radToDeg(q[5])),
              (behindAxis1 ? 4 : 0) | (behindLowerArm ? 2 : 0) | (axis5Negative ? 1 : 0)};
  return c;
}

}  // namespace spira
