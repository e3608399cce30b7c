#include "contour_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spira/base/units.h"

namespace spira::test {

std::vector<double> heightField(const TriangleMesh& mesh, double scale)
{
  std::vector<double> f;
  for (const auto& v : mesh.vertices) f.push_back(scale * v.z());
  return f;
}

std::vector<double> hemisphereDistance(const TriangleMesh& mesh, double radius)
{
  std::vector<double> f;
  for (const auto& v : mesh.vertices) f.push_back(radius * std::atan2(v.z(), std::hypot(v.x(), v.y())));
  return f;
}

TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b)
{
  TriangleMesh m = a;
  const int offset = static_cast<int>(a.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const auto& f : b.faces) m.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  return m;
}

TriangleMesh translated(TriangleMesh m, const Vec3& offset)
{
  for (auto& v : m.vertices) v += offset;
  return m;
}

TriangleMesh flatFork()
{
  TriangleMesh m;
  const int nx = 6, ny = 10;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.vertices.emplace_back(i - 3.0, static_cast<double>(j), 0.0);
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (j >= 5 && (i == 2 || i == 3)) continue;
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return m;
}

double distanceToPolygon(const Vec3& p, double r, int n)
{
  double best = std::numeric_limits<double>::infinity();
  for (int j = 0; j < n; ++j) {
    const double a0 = 2 * kPi * j / n, a1 = 2 * kPi * (j + 1) / n;
    const Vec3 a(r * std::cos(a0), r * std::sin(a0), p.z()), b(r * std::cos(a1), r * std::sin(a1), p.z());
    const Vec3 ab = b - a;
    const double u = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + u * ab - p).norm());
  }
  return best;
}

}  // namespace spira::test
