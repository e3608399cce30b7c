#include "spira/kinematics/jacobian.h"

namespace spira {

Jacobian geometricJacobian(const KinematicChain& chain, const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Vec3& pointInTip)
{
  const auto n = static_cast<Eigen::Index>(chain.size());
  Eigen::Matrix3Xd points(3, n), axes(3, n);
  const Transform tip = chain.forward(q, points, axes);
  const Vec3 p = tip * pointInTip;
  Jacobian j(6, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    j.col(i).head<3>() = axes.col(i).cross(p - points.col(i));
    j.col(i).tail<3>() = axes.col(i);
  }
  return j;
}

}  // namespace spira
