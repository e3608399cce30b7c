#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "spira/base/transform.h"
#include "spira/kinematics/chain_joint.h"

namespace spira {

// A serial chain of revolute joints between two links of a robot description, e.g. a URDF's
// base_link -> tool0. Fixed joints are folded into the revolute joints' origins, so the chain is
// just: T_base_tip(q) = O_1 R_1(q_1) O_2 R_2(q_2) ... O_n R_n(q_n) T_tip, where O_i is joint i's
// origin and R_i the rotation about its axis. Lengths are mm (URDF metres are converted on read).
class KinematicChain {
 public:
  KinematicChain(std::string baseLink, std::string tipLink, std::vector<ChainJoint> joints,
                 const Transform& tipOffset);

  // Reads a URDF and extracts the chain from `baseLink` to `tipLink`. The path from the base up to
  // the links' common ancestor must be fixed joints only (so "base" -> "tool0" works when "base" is
  // a fixed child of "base_link"). Throws InputError when the file does not parse, a link is
  // missing, or a movable joint in the chain is not revolute (prismatic, planar, floating).
  static KinematicChain fromUrdfFile(const std::string& path, const std::string& baseLink,
                                     const std::string& tipLink);
  static KinematicChain fromUrdfString(const std::string& xml, const std::string& baseLink,
                                       const std::string& tipLink);

  const std::string& baseLink() const { return baseLink_; }
  const std::string& tipLink() const { return tipLink_; }
  size_t size() const { return joints_.size(); }
  const std::vector<ChainJoint>& joints() const { return joints_; }
  const ChainJoint& joint(size_t i) const { return joints_.at(i); }
  // T_lastJoint_tip: fixed joints after the last revolute joint.
  const Transform& tipOffset() const { return tipOffset_; }

  // T_base_tip for joint values q (rad, size() of them). Throws InputError on a wrong count or NaN.
  Transform forward(const Eigen::Ref<const Eigen::VectorXd>& q) const;
  // The same, and for each joint i a point on its axis (column i of `axisPoints`, base frame, mm)
  // and the axis direction (column i of `axisDirections`). Both must have size() columns.
  Transform forward(const Eigen::Ref<const Eigen::VectorXd>& q, Eigen::Ref<Eigen::Matrix3Xd> axisPoints,
                    Eigen::Ref<Eigen::Matrix3Xd> axisDirections) const;

  // Smallest distance (rad) of any joint to its position limits: negative when a joint is outside.
  double limitMargin(const Eigen::Ref<const Eigen::VectorXd>& q) const;

 private:
  void checkInput(const Eigen::Ref<const Eigen::VectorXd>& q) const;

  std::string baseLink_;
  std::string tipLink_;
  std::vector<ChainJoint> joints_;
  Transform tipOffset_ = Transform::Identity();
};

}  // namespace spira
