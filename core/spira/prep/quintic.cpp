#include "spira/prep/quintic.h"

namespace spira {

Quintic3 Quintic3::hermite(const Vec3& p0, const Vec3& v0, const Vec3& a0, const Vec3& p1, const Vec3& v1,
                           const Vec3& a1)
{
  const Vec3 d = p1 - p0;
  Quintic3 q;
  q.c[0] = p0;
  q.c[1] = v0;
  q.c[2] = 0.5 * a0;
  q.c[3] = 10.0 * d - 6.0 * v0 - 4.0 * v1 - 1.5 * a0 + 0.5 * a1;
  q.c[4] = -15.0 * d + 8.0 * v0 + 7.0 * v1 + 1.5 * a0 - a1;
  q.c[5] = 6.0 * d - 3.0 * v0 - 3.0 * v1 - 0.5 * a0 + 0.5 * a1;
  return q;
}

Vec3 Quintic3::value(double u) const
{
  return c[0] + u * (c[1] + u * (c[2] + u * (c[3] + u * (c[4] + u * c[5]))));
}

Vec3 Quintic3::derivative(double u) const
{
  return c[1] + u * (2.0 * c[2] + u * (3.0 * c[3] + u * (4.0 * c[4] + u * 5.0 * c[5])));
}

Vec3 Quintic3::secondDerivative(double u) const
{
  return 2.0 * c[2] + u * (6.0 * c[3] + u * (12.0 * c[4] + u * 20.0 * c[5]));
}

ParabolaDerivatives parabolaDerivatives(const Vec3& m0, const Vec3& m1, const Vec3& m2, double l01,
                                        double l12, int node)
{
  // Lagrange basis on the nodes t0 = 0, t1 = l01, t2 = l01 + l12.
  const double t0 = 0.0, t1 = l01, t2 = l01 + l12;
  const double t = node == 0 ? t0 : (node == 1 ? t1 : t2);
  const double w0 = 1.0 / ((t0 - t1) * (t0 - t2));
  const double w1 = 1.0 / ((t1 - t0) * (t1 - t2));
  const double w2 = 1.0 / ((t2 - t0) * (t2 - t1));
  ParabolaDerivatives d;
  d.first =
      w0 * ((t - t1) + (t - t2)) * m0 + w1 * ((t - t0) + (t - t2)) * m1 + w2 * ((t - t0) + (t - t1)) * m2;
  d.second = 2.0 * (w0 * m0 + w1 * m1 + w2 * m2);
  return d;
}

}  // namespace spira
