#pragma once

#include <Eigen/Core>

#include "spira/base/transform.h"

namespace spira {

// Smallest over largest singular value of a 3x3 matrix, in [0, 1]; 0 when it is singular.
double singularValueRatio(const Mat3& m);

// Dexterity of a 6R arm with a spherical wrist, from its 6x6 geometric Jacobian taken AT THE WRIST
// CENTRE (jacobian.h with pointInTip = the wrist centre). There the Jacobian is block triangular,
//   J = [ A  0 ]   A: wrist-centre velocity from joints 1-3 (mm/rad)
//       [ B  C ]   C: angular velocity from joints 4-6 (unitless)
// so det J = det A * det C and the arm is singular exactly when A (shoulder or elbow singularity)
// or C (wrist singularity) is. Dexterity = min(ratio(A), ratio(C)) with ratio = sigma_min/sigma_max:
// unit-free, 1 at best, 0 at any singularity. This is the thesis' omega_2 = xi_min/xi_max
// (004_bd0df31205c0c3c0.txt §1.4.2, Eq. 1.8) applied to a translational and a rotational block separately
// (its Fig. 4.4 shows the two), but on the decoupled 3x3 blocks: the 3x6 blocks of a 6R arm keep full rank at
// its singularities (the other three joints still move the TCP), so they could never reach 0.
double armDexterity(const Eigen::Matrix<double, 6, 6>& jacobianAtWristCentre);

}  // namespace spira
