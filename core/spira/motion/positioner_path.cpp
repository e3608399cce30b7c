#include "spira/motion/positioner_path.h"

#include <cmath>

#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"

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

}  // namespace

PositionerPath placeOnPositioner(const Trajectory& path, const JointPathSetup& setup,
                                 const MotionParams& params, Progress& progress)
{
  const TiltRotatePositioner& positioner = *setup.positioner;
  const TableAxis axis = rotationAxisInTable(positioner);
  const Vec3 reference = axis.direction.unitOrthogonal();
  const double tolerance = degToRad(params.buildTiltToleranceDeg);
  PositionerPath out;
  out.axes.resize(path.size());
  out.reached.assign(path.size(), false);
  Eigen::Vector2d e = setup.positionerSeed;
  double previousAzimuth = 0.0;
  for (size_t i = 0; i < path.size(); ++i) {
    if (i % kCancelStride == 0) progress.checkCancel();
    const TrajectoryPoint& point = path.points[i];
    const Vec3 buildInTable = (setup.tablePart.linear() * point.build).normalized();
    const double azimuth =
        angleAbout(axis.direction, reference, setup.tablePart * point.position - axis.point);
    // The table turns the part by the point's own turn about the axis, so the point stays put.
    const double target =
        params.turntableFollowsPoint && i > 0 ? e[1] - wrapToPi(azimuth - previousAzimuth) : e[1];
    const std::optional<Eigen::Vector2d> solved =
        positioner.solveWithin(buildInTable, tolerance, target, e[0]);
    if (solved) e = *solved;
    out.reached[i] = solved.has_value();
    out.axes[i] = e;
    previousAzimuth = azimuth;
  }
  return out;
}

}  // namespace spira
