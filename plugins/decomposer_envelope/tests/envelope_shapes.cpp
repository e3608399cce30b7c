#include "envelope_shapes.h"

#include <cmath>
#include <vector>

#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira::test {

TriangleMesh slopedCylinder(double r, double h0, double slope, int segments, int rings)
{
  TriangleMesh m = makeOpenCylinder(r, 1.0, segments, rings);
  for (Vec3& v : m.vertices) v.z() *= h0 + v.x() * std::tan(slope);
  return m;
}

TriangleMesh obliqueCylinder(double r, double h, double lean, int segments, int rings)
{
  TriangleMesh m = makeOpenCylinder(r, h, segments, rings);
  for (Vec3& v : m.vertices) v.x() += v.z() * std::tan(lean);
  return m;
}

TriangleMesh bulgedWall(double neck, int segments)
{
  const double rc = neck + 10, zc = 25, rho = 12;
  const double leave = std::acos((neck - rc) / rho);  // where the bead meets the neck, ~146.4 deg
  std::vector<Eigen::Vector2d> profile;
  const double zLow = zc - rho * std::sin(leave);
  for (int i = 0; i <= 18; ++i) profile.emplace_back(neck, zLow * i / 18.0);
  // Round the bead counter-clockwise in the (r, z) plane: down to its bottom, out, up, back in.
  const int arc = 120;
  for (int i = 1; i < arc; ++i) {
    const double phi = -leave + 2 * leave * i / arc;
    profile.emplace_back(rc + rho * std::cos(phi), zc + rho * std::sin(phi));
  }
  const double zHigh = zc + rho * std::sin(leave);
  for (int i = 0; i <= 18; ++i) profile.emplace_back(neck, zHigh + (50 - zHigh) * i / 18.0);
  return makeRevolved(profile, segments);
}

TriangleMesh archTube(double bend, double r, int segments, int rings)
{
  TriangleMesh m;
  for (int i = 0; i <= rings; ++i) {
    const double phi = kPi * i / rings;
    const Vec3 centre(bend * std::cos(phi), 0, bend * std::sin(phi));
    const Vec3 out(std::cos(phi), 0, std::sin(phi));
    for (int j = 0; j < segments; ++j) {
      const double psi = 2 * kPi * j / segments;
      m.vertices.push_back(centre + r * (std::cos(psi) * out + std::sin(psi) * Vec3::UnitY()));
    }
  }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const int a = i * segments + j, b = i * segments + (j + 1) % segments;
      const int c = a + segments, d = b + segments;
      m.faces.push_back({a, b, d});
      m.faces.push_back({a, d, c});
    }
  // Outward: compare the first face's normal with the direction away from the centre line.
  const Vec3 away = m.vertices[m.faces[0][0]] - Vec3(bend, 0, 0);
  if (m.faceNormal(0).dot(away) < 0)
    for (Face& f : m.faces) std::swap(f[1], f[2]);
  return m;
}

}  // namespace spira::test
