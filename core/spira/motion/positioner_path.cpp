#include "spira/motion/positioner_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"
#include "spira/path/tool_tilt.h"

namespace spira {

namespace {

constexpr size_t kCancelStride = 4096;

// The angle about unit `axis` from `from` to `to` (both projected off the axis).
double angleAbout(const Vec3& axis, const Vec3& from, const Vec3& to)
{
  const Vec3 f = from - from.dot(axis) * axis;
  const Vec3 t = to - to.dot(axis) * axis;
  return std::atan2(axis.dot(f.cross(t)), f.dot(t));
}

// The positioner's rotation axis in its table frame (point and unit direction).
struct TableAxis {
  Vec3 point = Vec3::Zero();
  Vec3 direction = Vec3::UnitZ();
};

TableAxis rotationAxisInTable(const TiltRotatePositioner& positioner)
{
  const KinematicChain& chain = positioner.chain();
  const Transform tableJoint = chain.tipOffset().inverse();  // T_table_joint2
  return {tableJoint.translation(), (tableJoint.linear() * chain.joint(1).axis).normalized()};
}

// The whole turns k that put [lo + 2 pi k, hi + 2 pi k] inside [lower, upper], nearest 0, if any.
bool fewestTurns(double lo, double hi, double lower, double upper, int& turns)
{
  const double fewest = std::ceil((lower - lo) / (2.0 * kPi) - 1e-12);
  const double most = std::floor((upper - hi) / (2.0 * kPi) + 1e-12);
  if (!(fewest <= most) || !std::isfinite(fewest) || !std::isfinite(most)) return false;
  turns = static_cast<int>(std::clamp(0.0, fewest, most));
  return true;
}

}  // namespace

std::array<int, 2> windToFit(std::vector<Eigen::Vector2d>& axes, const std::vector<bool>& reached,
                             const KinematicChain& chain, double marginRad)
{
  std::array<int, 2> out{};
  for (Eigen::Index k = 0; k < 2; ++k) {
    const ChainJoint& joint = chain.joint(static_cast<size_t>(k));
    if (!(joint.upper - joint.lower >= 2.0 * kPi) || !std::isfinite(joint.upper - joint.lower)) continue;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (size_t i = 0; i < axes.size(); ++i)
      if (reached[i]) {
        lo = std::min(lo, axes[i][k]);
        hi = std::max(hi, axes[i][k]);
      }
    if (!(lo <= hi)) continue;
    int turns = 0;
    if (!fewestTurns(lo, hi, joint.lower + marginRad, joint.upper - marginRad, turns) &&
        !fewestTurns(lo, hi, joint.lower, joint.upper, turns))
      turns =
          static_cast<int>(std::round((0.5 * (joint.lower + joint.upper) - 0.5 * (lo + hi)) / (2.0 * kPi)));
    if (turns == 0) continue;
    for (Eigen::Vector2d& e : axes) e[k] += 2.0 * kPi * turns;
    out[static_cast<size_t>(k)] = turns;
  }
  return out;
}

PositionerPath placeOnPositioner(const Trajectory& path, const JointPathSetup& setup,
                                 const MotionParams& params, Progress& progress)
{
  const TiltRotatePositioner& positioner = *setup.positioner;
  const TableAxis axis = rotationAxisInTable(positioner);
  const double tolerance = degToRad(params.buildTiltToleranceDeg);
  PositionerPath out;
  out.axes.resize(path.size());
  out.reached.assign(path.size(), false);
  Eigen::Vector2d e = setup.positionerSeed;
  Vec3 previous = Vec3::Zero();  // the previous point about the axis: its offset off the axis
  for (size_t i = 0; i < path.size(); ++i) {
    if (i % kCancelStride == 0) progress.checkCancel();
    const TrajectoryPoint& point = path.points[i];
    const Vec3 buildInTable = (setup.tablePart.linear() * upDirection(path, i)).normalized();
    Vec3 offAxis = setup.tablePart * point.position - axis.point;
    offAxis -= offAxis.dot(axis.direction) * axis.direction;
    // The table turns the part by the point's own turn about the axis, so the point stays put;
    // unless the step turns it by a radian or more (an end within a step's length of the axis, a
    // closure point on it), where that turn is noise and turning the table hardly moves the point.
    double target = e[1];
    const double step = i > 0 ? (point.position - path.points[i - 1].position).norm() : 0.0;
    if (params.turntableFollowsPoint && i > 0 && std::min(offAxis.norm(), previous.norm()) > step)
      target -= angleAbout(axis.direction, previous, offAxis);
    const std::optional<Eigen::Vector2d> solved =
        positioner.solveWithin(buildInTable, tolerance, target, e[0]);
    if (solved) e = *solved;
    out.reached[i] = solved.has_value();
    out.axes[i] = e;
    previous = offAxis;
  }
  out.turns = windToFit(out.axes, out.reached, positioner.chain(), degToRad(params.limitMarginDeg));
  return out;
}

}  // namespace spira
