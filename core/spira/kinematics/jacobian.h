#pragma once

#include <Eigen/Core>

#include "spira/base/transform.h"
#include "spira/kinematics/kinematic_chain.h"

namespace spira {

// Geometric Jacobian: column i maps joint i's rate (rad/s) to the twist of a point fixed in the
// tip frame, in the chain's base frame. Rows 0-2: linear velocity of the point (mm per rad),
// rows 3-5: angular velocity of the tip (rad per rad).
using Jacobian = Eigen::Matrix<double, 6, Eigen::Dynamic>;

Jacobian geometricJacobian(const KinematicChain& chain, const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Vec3& pointInTip = Vec3::Zero());

}  // namespace spira
