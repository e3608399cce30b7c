#include "spira/kinematics/opw_model.h"

#include <cmath>

#include "spira/kinematics/angle_wrap.h"

namespace spira {

namespace {

Mat3 rotZ(double a)
{
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r << c, -s, 0, s, c, 0, 0, 0, 1;
  return r;
}

Mat3 rotY(double a)
{
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r << c, 0, s, 0, 1, 0, -s, 0, c;
  return r;
}

}  // namespace

OpwModel::OpwModel(const OpwParameters& parameters, const Transform& baseOpw, const Transform& flangeTip)
    : p_(parameters),
      baseOpw_(baseOpw),
      flangeTip_(flangeTip),
      baseOpwInverse_(baseOpw.inverse()),
      flangeTipInverse_(flangeTip.inverse()),
      psi3_(std::atan2(parameters.a2, parameters.c3)),
      k_(std::hypot(parameters.a2, parameters.c3))
{
}

Vec3 OpwModel::wristCentreInTip() const
{
  return flangeTipInverse_ * Vec3(0.0, 0.0, -p_.c4);
}

JointVector OpwModel::toOpw(const JointVector& q) const
{
  JointVector t;
  for (int i = 0; i < 6; ++i)
    t[i] = p_.signs[static_cast<size_t>(i)] * q[i] - p_.offsets[static_cast<size_t>(i)];
  return t;
}

JointVector OpwModel::fromOpw(const JointVector& theta) const
{
  JointVector q;
  for (int i = 0; i < 6; ++i)
    q[i] = p_.signs[static_cast<size_t>(i)] * (theta[i] + p_.offsets[static_cast<size_t>(i)]);
  return q;
}

Transform OpwModel::opwFlange(const JointVector& t) const
{
  const double reach = wristReach(t);
  const double up = p_.c2 * std::cos(t[1]) + k_ * std::cos(t[1] + t[2] + psi3_);
  const double c1 = std::cos(t[0]), s1 = std::sin(t[0]);
  const Vec3 wrist(reach * c1 - p_.b * s1, reach * s1 + p_.b * c1, up + p_.c1);
  Transform f = Transform::Identity();
  f.linear() = rotZ(t[0]) * rotY(t[1] + t[2]) * rotZ(t[3]) * rotY(t[4]) * rotZ(t[5]);
  f.translation() = wrist + p_.c4 * f.linear().col(2);
  return f;
}

Transform OpwModel::forward(const JointVector& q) const
{
  return baseOpw_ * opwFlange(toOpw(q)) * flangeTip_;
}

double OpwModel::wristReach(const JointVector& t) const
{
  return p_.a1 + p_.c2 * std::sin(t[1]) + k_ * std::sin(t[1] + t[2] + psi3_);
}

double OpwModel::elbowAngle(const JointVector& t) const
{
  return wrapToPi(t[2] + psi3_);
}

ArmConfiguration OpwModel::configurationOf(const JointVector& q) const
{
  const JointVector t = toOpw(q);
  ArmConfiguration c;
  c.front = wristReach(t) >= 0.0;
  c.up = elbowAngle(t) >= 0.0;
  c.noFlip = wrapToPi(t[4]) >= 0.0;
  return c;
}

bool OpwModel::solve(const Transform& opwFlange, const ArmConfiguration& configuration, double theta4Hint,
                     JointVector& theta) const
{
  const Mat3& r = opwFlange.linear();
  const Vec3 c = opwFlange.translation() - p_.c4 * r.col(2);  // wrist centre

  // Joint 1: the wrist centre must sit at (+-reach, b) in the frame turning with joint 1.
  const double reach2 = c.x() * c.x() + c.y() * c.y() - p_.b * p_.b;
  if (reach2 < 0.0) return false;
  const double reach = (configuration.front ? 1.0 : -1.0) * std::sqrt(reach2);
  theta[0] = std::atan2(c.y(), c.x()) - std::atan2(p_.b, reach);

  // Joints 2 and 3: a planar two-link arm from axis 2 to the wrist centre.
  const double u = reach - p_.a1, w = c.z() - p_.c1;
  const double cosElbow = (u * u + w * w - p_.c2 * p_.c2 - k_ * k_) / (2.0 * p_.c2 * k_);
  if (!(std::abs(cosElbow) <= 1.0 + 1e-12)) return false;
  const double elbow = (configuration.up ? 1.0 : -1.0) * std::acos(std::max(-1.0, std::min(1.0, cosElbow)));
  theta[2] = elbow - psi3_;
  theta[1] = std::atan2(u, w) - std::atan2(k_ * std::sin(elbow), p_.c2 + k_ * std::cos(elbow));

  // Wrist: R_wrist = Rz(t4) Ry(t5) Rz(t6), a ZYZ Euler decomposition.
  const Mat3 rw = (rotZ(theta[0]) * rotY(theta[1] + theta[2])).transpose() * r;
  const double s5 = std::hypot(rw(0, 2), rw(1, 2));
  if (s5 < 1e-12) {
    // Axes 4 and 6 line up: only theta4 + theta6 (or theta4 - theta6) is defined.
    theta[3] = theta4Hint;
    if (rw(2, 2) > 0.0) {
      theta[4] = 0.0;
      theta[5] = std::atan2(rw(1, 0), rw(0, 0)) - theta4Hint;
    } else {
      theta[4] = configuration.noFlip ? kPi : -kPi;
      theta[5] = theta4Hint - std::atan2(-rw(1, 0), -rw(0, 0));
    }
    return true;
  }
  const double sign = configuration.noFlip ? 1.0 : -1.0;
  theta[3] = std::atan2(sign * rw(1, 2), sign * rw(0, 2));
  theta[4] = sign * std::atan2(s5, rw(2, 2));
  theta[5] = std::atan2(sign * rw(2, 1), -sign * rw(2, 0));
  return true;
}

}  // namespace spira
