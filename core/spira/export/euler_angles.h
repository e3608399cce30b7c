#pragma once

#include "spira/base/transform.h"

namespace spira {

// Robot controllers write orientations as three angles. KUKA and FANUC use the same matrix,
//   R = Rz(z) * Ry(y) * Rx(x),
// read as intrinsic rotations Z, Y', X'' (KUKA A, B, C) or as fixed-axis rotations X, Y, Z
// (FANUC W, P, R). So (A, B, C)_KUKA = (R, P, W)_FANUC for one matrix (004_bd0df31205c0c3c0.txt Appendix B).
// The angles are always computed from the full rotation matrix, never copied from another convention.
//
// Ranges: z and x in (-pi, pi], y in [-pi/2, pi/2]. At gimbal lock (y = +-pi/2, where only z - x
// or z + x is defined) x is set to 0 and z carries the whole rotation about the vertical axis.
// All angles in radians.
struct ZyxAngles {
  double z = 0.0;
  double y = 0.0;
  double x = 0.0;
};

ZyxAngles zyxAnglesFromRotation(const Mat3& r);
Mat3 rotationFromZyxAngles(const ZyxAngles& angles);

// KUKA KRL E6POS/FRAME orientation: A about Z, B about Y', C about X''.
struct KukaAbc {
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
};
KukaAbc kukaAbcFromRotation(const Mat3& r);
Mat3 rotationFromKukaAbc(const KukaAbc& abc);

// FANUC XYZWPR orientation: W about X, P about Y, R about Z (fixed axes), R = Rz(r) Ry(p) Rx(w).
struct FanucWpr {
  double w = 0.0;
  double p = 0.0;
  double r = 0.0;
};
FanucWpr fanucWprFromRotation(const Mat3& r);
Mat3 rotationFromFanucWpr(const FanucWpr& wpr);

// The angle (radians) of the rotation that takes `a` to `b`: the distance tests use to compare
// orientations without comparing angle triples.
double rotationAngleBetween(const Mat3& a, const Mat3& b);

}  // namespace spira
