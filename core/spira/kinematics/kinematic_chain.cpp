#include "spira/kinematics/kinematic_chain.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spira/base/error.h"

namespace spira {

namespace {

// R(axis, angle) via Rodrigues, cheaper than going through a quaternion for one joint.
Mat3 axisRotation(const Vec3& axis, double angle)
{
  const double c = std::cos(angle), s = std::sin(angle), v = 1.0 - c;
  const double x = axis.x(), y = axis.y(), z = axis.z();
  Mat3 r;
  r << c + x * x * v, x * y * v - z * s, x * z * v + y * s,  //
      y * x * v + z * s, c + y * y * v, y * z * v - x * s,   //
      z * x * v - y * s, z * y * v + x * s, c + z * z * v;
  return r;
}

}  // namespace

KinematicChain::KinematicChain(std::string baseLink, std::string tipLink, std::vector<ChainJoint> joints,
                               const Transform& tipOffset)
    : baseLink_(std::move(baseLink)),
      tipLink_(std::move(tipLink)),
      joints_(std::move(joints)),
      tipOffset_(tipOffset)
{
  for (ChainJoint& j : joints_) {
    const double n = j.axis.norm();
    if (!(n > 1e-12) || !j.axis.allFinite())
      throw InputError("joint '" + j.name + "' has a zero or invalid axis",
                       "give every revolute joint a non-zero <axis xyz=...> in the robot description");
    j.axis /= n;
  }
}

void KinematicChain::checkInput(const Eigen::Ref<const Eigen::VectorXd>& q) const
{
  if (static_cast<size_t>(q.size()) != joints_.size())
    throw InputError("the chain " + baseLink_ + " -> " + tipLink_ + " has " + std::to_string(joints_.size()) +
                         " joints but " + std::to_string(q.size()) + " joint values were given",
                     "pass one value (rad) per revolute joint, first joint first");
  if (!q.allFinite())
    throw InputError("a joint value is not a finite number (NaN or infinity)",
                     "check the joint values fed to the kinematics");
}

Transform KinematicChain::forward(const Eigen::Ref<const Eigen::VectorXd>& q) const
{
  checkInput(q);
  Transform t = Transform::Identity();
  for (size_t i = 0; i < joints_.size(); ++i) {
    t = t * joints_[i].origin;
    t.linear() = t.linear() * axisRotation(joints_[i].axis, q[static_cast<Eigen::Index>(i)]);
  }
  return t * tipOffset_;
}

Transform KinematicChain::forward(const Eigen::Ref<const Eigen::VectorXd>& q,
                                  Eigen::Ref<Eigen::Matrix3Xd> axisPoints,
                                  Eigen::Ref<Eigen::Matrix3Xd> axisDirections) const
{
  checkInput(q);
  if (static_cast<size_t>(axisPoints.cols()) != joints_.size() ||
      static_cast<size_t>(axisDirections.cols()) != joints_.size())
    throw InternalError("KinematicChain::forward: axis matrices need one column per joint");
  Transform t = Transform::Identity();
  for (size_t i = 0; i < joints_.size(); ++i) {
    t = t * joints_[i].origin;
    const auto c = static_cast<Eigen::Index>(i);
    axisPoints.col(c) = t.translation();
    axisDirections.col(c) = t.linear() * joints_[i].axis;
    t.linear() = t.linear() * axisRotation(joints_[i].axis, q[c]);
  }
  return t * tipOffset_;
}

double KinematicChain::limitMargin(const Eigen::Ref<const Eigen::VectorXd>& q) const
{
  checkInput(q);
  double margin = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < joints_.size(); ++i) {
    const double v = q[static_cast<Eigen::Index>(i)];
    margin = std::min({margin, v - joints_[i].lower, joints_[i].upper - v});
  }
  return margin;
}

}  // namespace spira
