#include "spira/kinematics/tilt_rotate_positioner.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"
#include "spira/kinematics/angle_wrap.h"

namespace spira {

namespace {

// The angle that turns `from` to `to` about unit `axis` (both projected off the axis).
double angleAbout(const Vec3& axis, const Vec3& from, const Vec3& to)
{
  const Vec3 f = from - from.dot(axis) * axis;
  const Vec3 t = to - to.dot(axis) * axis;
  return std::atan2(axis.dot(f.cross(t)), f.dot(t));
}

}  // namespace

TiltRotatePositioner::TiltRotatePositioner(KinematicChain chain) : chain_(std::move(chain))
{
  if (chain_.size() != 2)
    throw InputError("a tilt-rotate positioner needs 2 revolute joints; the chain " + chain_.baseLink() +
                         " -> " + chain_.tipLink() + " has " + std::to_string(chain_.size()),
                     "choose the chain from the positioner's base link to its table link");
  Eigen::Matrix3Xd points(3, 2), dirs(3, 2);
  tableAtZero_ = chain_.forward(Axes::Zero(), points, dirs).linear();
  axis1_ = dirs.col(0).normalized();
  axis2_ = dirs.col(1).normalized();
  if (axis1_.cross(axis2_).norm() < 1e-6)
    throw InputError("the positioner axes '" + chain_.joint(0).name + "' and '" + chain_.joint(1).name +
                         "' are parallel, so they cannot turn a direction to the vertical",
                     "use a tilt-rotate positioner (tilt axis horizontal, rotation about the table normal)");
}

std::vector<TiltRotatePositioner::Axes> TiltRotatePositioner::solveAll(const Vec3& directionInTable,
                                                                       const Vec3& up,
                                                                       double freeRotation) const
{
  if (!directionInTable.allFinite() || !up.allFinite() || directionInTable.norm() < 1e-12 ||
      up.norm() < 1e-12)
    throw InputError("the positioner was asked to turn a zero or invalid direction",
                     "check the build directions of the path");
  // Rot(w1, e1) Rot(w2, e2) x = g, with x the direction in the base frame at the zero pose.
  const Vec3 x = (tableAtZero_ * directionInTable).normalized();
  const Vec3 g = up.normalized();
  const Vec3& w1 = axis1_;
  const Vec3& w2 = axis2_;
  const double c12 = w1.dot(w2);
  const double den = c12 * c12 - 1.0;
  const double alpha = (c12 * w2.dot(x) - w1.dot(g)) / den;
  const double beta = (c12 * w1.dot(g) - w2.dot(x)) / den;
  const Vec3 n = w1.cross(w2);
  const double gamma2 = (1.0 - alpha * alpha - beta * beta - 2.0 * alpha * beta * c12) / n.squaredNorm();
  if (gamma2 < -1e-12) return {};
  const double gamma = std::sqrt(std::max(0.0, gamma2));
  std::vector<Axes> out;
  for (double sign : {1.0, -1.0}) {
    // c: the direction after the rotation about axis 2, before the one about axis 1.
    const Vec3 c = alpha * w1 + beta * w2 + sign * gamma * n;
    const bool alongAxis2 = (x - x.dot(w2) * w2).norm() < 1e-12;
    const double e2 = alongAxis2 ? freeRotation : angleAbout(w2, x, c);
    const double e1 = angleAbout(w1, c, g);
    out.push_back(Axes(wrapToPi(e1), wrapToPi(e2)));
    if (gamma < 1e-12) break;  // both branches coincide
  }
  if (out.size() == 2 && out[0][0] < out[1][0]) std::swap(out[0], out[1]);
  return out;
}

std::optional<TiltRotatePositioner::Axes> TiltRotatePositioner::solve(const Vec3& directionInTable,
                                                                      const Axes& previous,
                                                                      const Vec3& up) const
{
  if (!previous.allFinite())
    throw InputError("the previous positioner axis values are not finite", "check the positioner seed");
  std::optional<Axes> best;
  double bestDistance = 0.0;
  for (Axes e : solveAll(directionInTable, up, previous[1])) {
    e[0] = nearestBranch(e[0], previous[0]);
    e[1] = nearestBranch(e[1], previous[1]);
    const double d = (e - previous).norm();
    if (!best || d < bestDistance) {
      best = e;
      bestDistance = d;
    }
  }
  return best;
}

std::optional<TiltRotatePositioner::Axes> TiltRotatePositioner::solveWithin(const Vec3& directionInTable,
                                                                            double tolerance, double rotation,
                                                                            double previousTilt,
                                                                            const Vec3& up) const
{
  if (!directionInTable.allFinite() || !up.allFinite() || directionInTable.norm() < 1e-12 ||
      up.norm() < 1e-12 || !std::isfinite(rotation) || !std::isfinite(previousTilt) ||
      !std::isfinite(tolerance) || tolerance < 0.0)
    throw InputError("the positioner was asked to turn a zero or invalid direction",
                     "check the build directions of the path and the positioner seed");
  const Vec3 x = (tableAtZero_ * directionInTable).normalized();
  const Vec3 g = up.normalized();
  const Vec3& w1 = axis1_;
  const Vec3& w2 = axis2_;
  // Rotating about w1 keeps a direction's elevation off the plane normal to w1, so after the best
  // tilt the direction Rot(w2, e2) x lies |asin(s) - asin(w1 . g)| from g, s = w1 . Rot(w2, e2) x.
  // s = a + rho cos(e2 - eta): the rotations within tolerance are those with s in [sLow, sHigh].
  const Vec3 along = x.dot(w2) * w2;
  const Vec3 across = x - along;
  const double a = w1.dot(along);
  const double p = w1.dot(across);
  const double q = w1.dot(w2.cross(across));
  const double rho = std::hypot(p, q);
  const double elevation = std::asin(std::clamp(w1.dot(g), -1.0, 1.0));
  const double sLow = std::sin(std::max(elevation - tolerance, -kPi / 2.0));
  const double sHigh = std::sin(std::min(elevation + tolerance, kPi / 2.0));
  constexpr double kSlack = 1e-12;
  double e2 = rotation;
  if (rho < kSlack) {
    if (a < sLow - kSlack || a > sHigh + kSlack) return std::nullopt;
  } else {
    const double eta = std::atan2(q, p);
    const double cLow = std::max((sLow - a) / rho, -1.0);
    const double cHigh = std::min((sHigh - a) / rho, 1.0);
    if (cLow > cHigh + kSlack) return std::nullopt;
    const double u = wrapToPi(rotation - eta);
    const double c = std::cos(u);
    if (c < cLow || c > cHigh) {
      // The nearest edge of the allowed set {u : cos u in [cLow, cHigh]} (one or two arcs).
      double best = 0.0;
      bool have = false;
      for (double edge : {std::acos(std::min(cHigh, 1.0)), std::acos(std::max(cLow, -1.0))})
        for (double sign : {1.0, -1.0}) {
          const double step = wrapToPi(sign * edge - u);
          if (!have || std::abs(step) < std::abs(best)) {
            best = step;
            have = true;
          }
        }
      e2 = rotation + best;
    }
  }
  const Vec3 c = Eigen::AngleAxisd(e2, w2) * x;
  const double e1 = nearestBranch(angleAbout(w1, c, g), previousTilt);
  return Axes(e1, e2);
}

}  // namespace spira
