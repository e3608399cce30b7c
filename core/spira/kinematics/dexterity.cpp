#include "spira/kinematics/dexterity.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace spira {

double singularValueRatio(const Mat3& m)
{
  Eigen::SelfAdjointEigenSolver<Mat3> eig;
  eig.computeDirect(m.transpose() * m, Eigen::EigenvaluesOnly);
  const Vec3& l = eig.eigenvalues();  // ascending
  if (!(l[2] > 0.0)) return 0.0;
  return std::sqrt(std::max(0.0, l[0]) / l[2]);
}

double armDexterity(const Eigen::Matrix<double, 6, 6>& j)
{
  return std::min(singularValueRatio(j.block<3, 3>(0, 0)), singularValueRatio(j.block<3, 3>(3, 3)));
}

}  // namespace spira
