#include "geodesic_shapes.h"

#include <cmath>
#include <limits>

#include "spira/base/units.h"

namespace spira::test {

TriangleMesh makeTube(const std::function<double(double, double)>& radius,
                      const std::function<double(double)>& top, int segments, int rings)
{
  TriangleMesh m;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * kPi * i / segments;
      const double z = top(a) * j / rings;
      const double r = radius(a, z);
      m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), z);
    }
  auto id = [&](int i, int j) { return j * segments + (i % segments); };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

double Bump::radius(double alpha, double z) const
{
  double a = std::remainder(alpha, 2.0 * kPi);
  return R + bump * std::exp(-(a * a) / (sigmaAngle * sigmaAngle) - (z - zc) * (z - zc) / (sigmaZ * sigmaZ));
}

DecomposeInput Part::input() const
{
  DecomposeInput in{mesh, report.partClass, report.boundaryLoops.at(0), std::nullopt, std::nullopt};
  if (report.boundaryLoops.size() > 1) in.upper = report.boundaryLoops[1];
  return in;
}

Part makePart(TriangleMesh mesh)
{
  Part p;
  p.mesh = std::move(mesh);
  p.report = validateMesh(p.mesh);
  return p;
}

double angleOf(const Vec3& p)
{
  const double a = std::atan2(p.y(), p.x());
  return a < 0 ? a + 2.0 * kPi : a;
}

double polylineLength(const std::vector<Vec3>& line)
{
  double s = 0.0;
  for (size_t k = 1; k < line.size(); ++k) s += (line[k] - line[k - 1]).norm();
  return s;
}

double distanceToTube(const Vec3& p, const std::function<double(double, double)>& radius)
{
  auto at = [&](double a, double z) {
    const double r = radius(a, z);
    return (Vec3(r * std::cos(a), r * std::sin(a), z) - p).norm();
  };
  const double a0 = std::atan2(p.y(), p.x()), z0 = p.z();
  double best = std::numeric_limits<double>::infinity(), ba = a0, bz = z0;
  double da = 0.2, dz = 8.0;
  for (int level = 0; level < 6; ++level) {
    const double ca = ba, cz = bz;
    for (int i = -10; i <= 10; ++i)
      for (int j = -10; j <= 10; ++j) {
        const double a = ca + da * i / 10.0, z = cz + dz * j / 10.0;
        const double d = at(a, z);
        if (d < best) {
          best = d;
          ba = a;
          bz = z;
        }
      }
    da /= 5.0;
    dz /= 5.0;
  }
  return best;
}

}  // namespace spira::test
