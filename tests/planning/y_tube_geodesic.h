#pragma once

// The exact geodesic distance from the base of a YTube (y_tube.h) to its crotch saddle, by
// unrolling the developable pieces: up the trunk (distance = z) to a point Q of the crease where
// the trunk meets arm 1, straight across arm 1's unrolled cylinder to a point R of the crease where
// the two arms meet (the valley through the crotch), then along that crease to the saddle. The
// unrolled crease is an arch the straight segment may not cross, so the shortest path touches it
// at R and follows it; Q and R are searched on fine grids.

#include <algorithm>
#include <cmath>
#include <limits>

#include "planning/y_tube.h"
#include "spira/base/units.h"

namespace spira::test {

inline double yTubeSaddleDistance(const YTube& y)
{
  const double r = y.radius, s = std::sin(y.alpha), c = std::cos(y.alpha), z0 = y.trunkTop;
  // Arm 1's unrolled coordinates: X = r psi around its axis (psi = pi on its inner line, facing
  // -x), T along it from O.
  const Vec3 d1(s, 0, c), e1(c, 0, -s), e2(0, 1, 0);
  auto unroll = [&](const Vec3& p, double* X, double* T) {
    const Vec3 w = p - y.origin();
    *T = w.dot(d1);
    double psi = std::atan2(w.dot(e2), w.dot(e1));
    if (psi < 0) psi += 2.0 * kPi;
    *X = r * psi;
  };
  // The crotch crease, for beta in [0, pi/2]: (X, T) = (r (pi - beta), (c / s) r cos(beta)); the
  // arm lies on the surface where T >= that arch.
  auto archT = [&](double X) { return -(c / s) * r * std::cos(X / r); };
  auto archLength = [&](double beta) {  // from the saddle (beta = 0) to beta, in 3-D = unrolled
    const int n = 2000;
    double len = 0.0;
    for (int i = 0; i < n; ++i) {
      const double b = beta * (i + 0.5) / n;
      len += r * std::sqrt(1.0 + std::pow(c / s * std::sin(b), 2)) * beta / n;
    }
    return len;
  };
  const int nq = 400, nr = 400;
  std::vector<double> arcR(nr + 1);
  for (int j = 0; j <= nr; ++j) arcR[static_cast<size_t>(j)] = archLength(0.5 * kPi * j / nr);
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= nq; ++i) {
    // Q on the trunk/arm-1 crease, x >= 0 side: z = z0 - r s cos(theta) / (1 + c).
    const double theta = 0.5 * kPi * i / nq;
    const Vec3 q(r * std::cos(theta), r * std::sin(theta), z0 - r * s * std::cos(theta) / (1.0 + c));
    double qx, qt;
    unroll(q, &qx, &qt);
    for (int j = 0; j <= nr; ++j) {
      const double beta = 0.5 * kPi * j / nr;
      const double rx = r * (kPi - beta), rt = (c / s) * r * std::cos(beta);
      // The segment Q -> R must stay on the arm: above the arch wherever it is over it.
      bool ok = true;
      for (int k = 1; k < 50 && ok; ++k) {
        const double u = k / 50.0;
        const double x = qx + u * (rx - qx), t = qt + u * (rt - qt);
        if (x > r * kPi / 2 && x <= r * kPi && t < archT(x) - 1e-9) ok = false;
      }
      if (!ok) continue;
      const double len = q.z() + std::hypot(rx - qx, rt - qt) + arcR[static_cast<size_t>(j)];
      best = std::min(best, len);
    }
  }
  return best;
}

}  // namespace spira::test
