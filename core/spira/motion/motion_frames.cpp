#include "spira/motion/motion_frames.h"

#include <cmath>

#include "spira/base/error.h"
#include "spira/kinematics/angle_wrap.h"
#include "spira/motion/positioner_path.h"
#include "spira/path/tool_frame.h"

namespace spira {

namespace {

// Reference and torch axes closer to opposite than this use parallel transport instead.
constexpr double kAntipodalCosine = -0.9;

// The angle about unit `axis` from `from` to `to` (both projected off the axis).
double angleAbout(const Vec3& axis, const Vec3& from, const Vec3& to)
{
  const Vec3 f = from - from.dot(axis) * axis;
  const Vec3 t = to - to.dot(axis) * axis;
  return std::atan2(axis.dot(f.cross(t)), f.dot(t));
}

// v turned by the smallest rotation that takes unit a onto unit b (a . b > -1).
Vec3 minimalRotation(const Vec3& a, const Vec3& b, const Vec3& v)
{
  const Vec3 k = a.cross(b);
  const double c = a.dot(b);
  return v * c + k.cross(v) + k * (k.dot(v) / (1.0 + c));
}

}  // namespace

Transform spinAboutTorch(double angle)
{
  Transform t = Transform::Identity();
  t.linear() = Eigen::AngleAxisd(angle, Vec3::UnitZ()).toRotationMatrix();
  return t;
}

MotionFrames buildMotionFrames(const Trajectory& path, const JointPathSetup& setup,
                               const MotionParams& params, Progress& progress)
{
  const size_t n = path.size();
  MotionFrames frames;
  frames.baseTcp0.resize(n);
  frames.chartOffset.assign(n, 0.0);
  frames.external.assign(n, Eigen::Vector2d::Zero());
  frames.positionerReached.assign(n, true);
  for (size_t i = 0; i < n; ++i) {
    const TrajectoryPoint& p = path.points[i];
    if (!p.position.allFinite() || !p.build.allFinite() || !p.tangent.allFinite() || p.build.norm() < 1e-12)
      throw InputError("path point " + std::to_string(i) + " has a non-finite position or no build direction",
                       "recompute the trajectory before solving the robot motion");
  }

  std::vector<Transform> basePart(n, setup.basePart);
  if (setup.positioner) {
    PositionerPath placed = placeOnPositioner(path, setup, params, progress);
    frames.external = std::move(placed.axes);
    frames.positionerReached = std::move(placed.reached);
    for (size_t i = 0; i < n; ++i)
      basePart[i] = setup.basePositioner * setup.positioner->forward(frames.external[i]) * setup.tablePart;
  }

  Vec3 meanAxis = Vec3::Zero();
  for (size_t i = 0; i < n; ++i) {
    frames.baseTcp0[i] = basePart[i] * toolFrame(path.points[i], 0.0);
    meanAxis += frames.baseTcp0[i].linear().col(2);
  }
  if (n == 0) return frames;
  // The mean torch axis is the reference, so that no point's axis is far from it; a path whose
  // axes cancel out (never a deposition path) falls back to its first axis.
  frames.referenceAxis = meanAxis.norm() > 1e-6 * static_cast<double>(n)
                             ? Vec3(meanAxis.normalized())
                             : Vec3(frames.baseTcp0[0].linear().col(2));
  Vec3 referenceX = Vec3::UnitX() - Vec3::UnitX().dot(frames.referenceAxis) * frames.referenceAxis;
  if (referenceX.norm() < 0.1)
    referenceX = Vec3::UnitY() - Vec3::UnitY().dot(frames.referenceAxis) * frames.referenceAxis;
  referenceX.normalize();

  Vec3 previousX = referenceX, previousZ = frames.referenceAxis;
  for (size_t i = 0; i < n; ++i) {
    const Mat3& r = frames.baseTcp0[i].linear();
    const Vec3 z = r.col(2);
    const Vec3 chartX = z.dot(frames.referenceAxis) > kAntipodalCosine
                            ? minimalRotation(frames.referenceAxis, z, referenceX)
                            : minimalRotation(previousZ, z, previousX);
    const double offset = angleAbout(z, r.col(0), chartX);
    frames.chartOffset[i] = i == 0 ? offset : nearestBranch(offset, frames.chartOffset[i - 1]);
    previousX = chartX;
    previousZ = z;
  }
  return frames;
}

}  // namespace spira
