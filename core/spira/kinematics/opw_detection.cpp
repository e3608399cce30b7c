#include "spira/kinematics/opw_detection.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "spira/kinematics/angle_wrap.h"

namespace spira {

namespace {

constexpr double kAngleTol = 1e-6;   // rad: parallel / perpendicular tests
constexpr double kLengthTol = 1e-3;  // mm: intersecting axes
// The closed form only seeds a Newton refinement on the true chain, so the model may differ from
// the chain by rounding in the description (e.g. rpy written as 1.5708); beyond this it is refused.
constexpr double kModelPositionTol = 1e-2;     // mm
constexpr double kModelOrientationTol = 1e-5;  // rad

struct Line {
  Vec3 point;
  Vec3 dir;  // unit
};

// Closest point on `a` to line `b` and the distance between them; false for parallel lines.
bool closestPoint(const Line& a, const Line& b, Vec3& onA, double& distance)
{
  const Vec3 n = a.dir.cross(b.dir);
  const double n2 = n.squaredNorm();
  if (n2 < kAngleTol * kAngleTol) return false;
  const Vec3 d = b.point - a.point;
  const double t = d.cross(b.dir).dot(n) / n2;
  onA = a.point + t * a.dir;
  distance = std::abs(d.dot(n)) / std::sqrt(n2);
  return true;
}

double distanceToLine(const Vec3& p, const Line& l)
{
  const Vec3 d = p - l.point;
  return (d - d.dot(l.dir) * l.dir).norm();
}

OpwDetection refuse(const std::string& why)
{
  OpwDetection d;
  d.reason = why;
  return d;
}

std::string jointName(const KinematicChain& chain, size_t i)
{
  return "joint " + std::to_string(i + 1) + " ('" + chain.joint(i).name + "')";
}

double sign(double v)
{
  return v < 0.0 ? -1.0 : 1.0;
}

}  // namespace

OpwDetection detectOpw(const KinematicChain& chain)
{
  if (chain.size() != 6)
    return refuse("the chain " + chain.baseLink() + " -> " + chain.tipLink() + " has " +
                  std::to_string(chain.size()) + " revolute joints, not 6");

  // Axes at the zero pose, in the base frame.
  Eigen::Matrix3Xd points(3, 6), dirs(3, 6);
  const Transform tip0 = chain.forward(JointVector::Zero(), points, dirs);
  std::array<Line, 6> axis;
  for (int i = 0; i < 6; ++i) axis[static_cast<size_t>(i)] = {points.col(i), dirs.col(i).normalized()};
  const auto& [l1, l2, l3, l4, l5, l6] = axis;

  if (std::abs(l1.dir.dot(l2.dir)) > kAngleTol)
    return refuse(jointName(chain, 0) + " is not perpendicular to " + jointName(chain, 1));
  if (l2.dir.cross(l3.dir).norm() > kAngleTol)
    return refuse(jointName(chain, 1) + " and " + jointName(chain, 2) + " are not parallel");
  if (std::abs(l4.dir.dot(l5.dir)) > kAngleTol || std::abs(l6.dir.dot(l5.dir)) > kAngleTol)
    return refuse("wrist axis 5 is not perpendicular to axes 4 and 6");
  if (std::abs(l4.dir.dot(l2.dir)) > kAngleTol)
    return refuse(jointName(chain, 3) + " is not perpendicular to " + jointName(chain, 1));
  Vec3 wrist;
  double gap = 0.0;
  if (!closestPoint(l4, l5, wrist, gap) || gap > kLengthTol || distanceToLine(wrist, l6) > kLengthTol)
    return refuse("axes 4, 5 and 6 do not meet in one point (no spherical wrist)");

  // OPW frame: z along axis 1 (pointing up in the base frame), y along axis 2, a1 >= 0.
  OpwParameters p;
  p.signs[0] = static_cast<int>(sign(l1.dir.z()));
  const Vec3 z = p.signs[0] * l1.dir;
  const Vec3 origin = l1.point - l1.point.dot(l1.dir) * l1.dir;
  Vec3 y = l2.dir;
  const double a1 = (l2.point - origin).dot(y.cross(z));
  const double reachAtZero = (wrist - origin).dot(y.cross(z));
  p.signs[1] = std::abs(a1) > kLengthTol ? static_cast<int>(sign(a1)) : static_cast<int>(sign(reachAtZero));
  y *= p.signs[1];
  const Vec3 x = y.cross(z);
  Transform baseOpw = Transform::Identity();
  baseOpw.linear().col(0) = x;
  baseOpw.linear().col(1) = y;
  baseOpw.linear().col(2) = z;
  baseOpw.translation() = origin;
  const Transform opwBase = baseOpw.inverse();
  const Vec3 p2 = opwBase * l2.point, p3 = opwBase * l3.point, w = opwBase * wrist;
  const Mat3 toOpw = opwBase.linear();

  p.a1 = p2.x();
  p.c1 = p2.z();
  p.b = w.y();
  p.signs[2] = static_cast<int>(sign(toOpw.row(1).dot(l3.dir)));
  // Upper arm: axis 2 -> axis 3 in the arm plane.
  const double ux = p3.x() - p2.x(), uz = p3.z() - p2.z();
  p.c2 = std::hypot(ux, uz);
  if (p.c2 < kLengthTol) return refuse("axes 2 and 3 coincide (no upper arm)");
  const double theta2 = std::atan2(ux, uz);
  // Forearm: axis 3 -> wrist centre; axis 4 signed to point from axis 3 towards the wrist.
  const Vec3 a4 = toOpw * l4.dir;
  const Vec3 e(w.x() - p3.x(), 0.0, w.z() - p3.z());
  p.signs[3] = static_cast<int>(sign(e.dot(a4)));
  const Vec3 f = p.signs[3] * a4;
  const double theta23 = std::atan2(f.x(), f.z());
  const Mat3 forearm = Eigen::AngleAxisd(theta23, Vec3::UnitY()).toRotationMatrix();
  p.c3 = e.dot(forearm.col(2));
  p.a2 = e.dot(forearm.col(0));
  if (std::hypot(p.a2, p.c3) < kLengthTol)
    return refuse("axis 3 passes through the wrist centre (no forearm)");
  // Wrist: axis 5 = Rz(theta4) y in the forearm frame, signed so that |theta4| <= 90 deg.
  const Vec3 v5 = forearm.transpose() * (toOpw * l5.dir);
  p.signs[4] =
      std::abs(v5.y()) > kAngleTol ? static_cast<int>(sign(v5.y())) : static_cast<int>(sign(-v5.x()));
  const double theta4 = std::atan2(-p.signs[4] * v5.x(), p.signs[4] * v5.y());
  const Mat3 g = forearm * Eigen::AngleAxisd(theta4, Vec3::UnitZ()).toRotationMatrix();
  const Transform opwTip0 = opwBase * tip0;
  const Vec3 a6 = toOpw * l6.dir;
  const double alongAxis6 = (opwTip0.translation() - w).dot(a6);
  p.signs[5] = std::abs(alongAxis6) > kLengthTol ? static_cast<int>(sign(alongAxis6)) : 1;
  const Vec3 v6 = g.transpose() * (p.signs[5] * a6);
  const double theta5 = std::atan2(v6.x(), v6.z());
  const Mat3 h = g * Eigen::AngleAxisd(theta5, Vec3::UnitY()).toRotationMatrix();
  p.c4 = (opwTip0.translation() - w).dot(h.col(2));
  // Flange angle: a tip whose z is the flange axis keeps only a turn about it, which joint 6 absorbs.
  const Mat3 rest = h.transpose() * opwTip0.linear();
  double theta6 = 0.0;
  if ((rest.col(2) - Vec3::UnitZ()).norm() < kAngleTol) theta6 = std::atan2(rest(1, 0), rest(0, 0));
  const Mat3 flange = h * Eigen::AngleAxisd(theta6, Vec3::UnitZ()).toRotationMatrix();
  Transform flangeTip = Transform::Identity();
  flangeTip.linear() = flange.transpose() * opwTip0.linear();
  flangeTip.translation() = flange.transpose() * (opwTip0.translation() - w - p.c4 * h.col(2));
  if ((flangeTip.linear() - Mat3::Identity()).norm() < 1e-12) flangeTip.linear().setIdentity();

  const std::array<double, 6> zeroTheta{{0.0, theta2, theta23 - theta2, theta4, theta5, theta6}};
  for (size_t i = 0; i < 6; ++i) p.offsets[i] = wrapToPi(-zeroTheta[i]);

  OpwDetection d;
  d.model = OpwModel(p, baseOpw, flangeTip);
  // Verify on random joint vectors: the whole point is not to trust the derivation blindly.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (int s = 0; s < 64; ++s) {
    JointVector q;
    for (int i = 0; i < 6; ++i) q[i] = s == 0 ? 0.0 : angle(rng);
    const Transform a = chain.forward(q), b = d.model.forward(q);
    d.maxPositionError = std::max(d.maxPositionError, (a.translation() - b.translation()).norm());
    d.maxOrientationError =
        std::max(d.maxOrientationError, Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle());
  }
  if (d.maxPositionError > kModelPositionTol || d.maxOrientationError > kModelOrientationTol) {
    d.reason = "the OPW model derived from the chain differs from it by " +
               std::to_string(d.maxPositionError) + " mm / " + std::to_string(d.maxOrientationError) + " rad";
    return d;
  }
  d.ok = true;
  return d;
}

}  // namespace spira
