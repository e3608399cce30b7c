#pragma once

#include "spira/base/transform.h"

namespace spira {

// One interval of the sliding quintic (002_4d923f9355c20a15.txt §I.2.1.1, Eq. I.8):
// X(u) = c0 + c1 u + ... + c5 u^5, u in [0, 1], for the three coordinates at once.
struct Quintic3 {
  Vec3 c[6] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};

  // The quintic Hermite interpolant matching value, first and second derivative (with respect to u)
  // at both ends: X(0) = p0, X'(0) = v0, X''(0) = a0, X(1) = p1, X'(1) = v1, X''(1) = a1.
  static Quintic3 hermite(const Vec3& p0, const Vec3& v0, const Vec3& a0, const Vec3& p1, const Vec3& v1,
                          const Vec3& a1);

  Vec3 value(double u) const;
  Vec3 derivative(double u) const;
  Vec3 secondDerivative(double u) const;
};

// First and second derivatives, with respect to the chord-length parameter, of the parabola through
// three points. The parameter is 0 at m0, l01 at m1 and l01 + l12 at m2 (l01, l12 > 0: the chord
// lengths of the positions; a frame vector uses the positions' lengths too). `node` (0, 1 or 2) says
// at which of the three points the derivatives are taken: 1 is the centred rule of A.2.1, 0 and 2
// the one-sided rule at the ends of a run.
struct ParabolaDerivatives {
  Vec3 first;
  Vec3 second;
};
ParabolaDerivatives parabolaDerivatives(const Vec3& m0, const Vec3& m1, const Vec3& m2, double l01,
                                        double l12, int node);

}  // namespace spira
