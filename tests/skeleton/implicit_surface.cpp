#include "implicit_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace spira::test {

namespace {

// The six tetrahedra of a cube around its diagonal 0-7; corner c is at (c & 1, c >> 1 & 1, c >> 2 & 1).
constexpr int kTets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                             {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

}  // namespace

TriangleMesh meshImplicit(const std::function<double(const Vec3&)>& f, const BoundingBox& box, double cell)
{
  const Vec3 size = box.size();
  const int nx = static_cast<int>(std::ceil(size.x() / cell)) + 1;
  const int ny = static_cast<int>(std::ceil(size.y() / cell)) + 1;
  const int nz = static_cast<int>(std::ceil(size.z() / cell)) + 1;
  auto id = [&](int i, int j, int k) { return (static_cast<int64_t>(k) * ny + j) * nx + i; };
  auto position = [&](int64_t g) {
    const int64_t i = g % nx, j = (g / nx) % ny, k = g / (static_cast<int64_t>(nx) * ny);
    return Vec3(box.min.x() + cell * static_cast<double>(i), box.min.y() + cell * static_cast<double>(j),
                box.min.z() + cell * static_cast<double>(k));
  };
  std::vector<double> value(static_cast<size_t>(nx) * ny * nz);
  for (int64_t g = 0; g < static_cast<int64_t>(value.size()); ++g) {
    const double v = f(position(g));
    value[g] = v == 0.0 ? 1e-12 : v;  // no corner exactly on the surface: keeps the result manifold
  }

  TriangleMesh mesh;
  std::unordered_map<int64_t, int> edgeVertex;  // grid edge (a * N + b, a < b) -> mesh vertex
  const int64_t N = static_cast<int64_t>(value.size());
  auto crossing = [&](int64_t a, int64_t b) {
    if (a > b) std::swap(a, b);
    const auto [it, added] = edgeVertex.emplace(a * N + b, static_cast<int>(mesh.vertices.size()));
    if (added) {
      const double t = value[a] / (value[a] - value[b]);
      mesh.vertices.push_back(position(a) + t * (position(b) - position(a)));
    }
    return it->second;
  };
  // Faces the outside (positive values).
  auto emit = [&](int p, int q, int r, const Vec3& outward) {
    const Vec3 n = (mesh.vertices[q] - mesh.vertices[p]).cross(mesh.vertices[r] - mesh.vertices[p]);
    if (n.dot(outward) < 0) std::swap(q, r);
    mesh.faces.push_back({p, q, r});
  };

  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i) {
        int64_t corner[8];
        for (int c = 0; c < 8; ++c) corner[c] = id(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1));
        for (const auto& tet : kTets) {
          std::vector<int64_t> in, out;
          for (int c : tet) (value[corner[c]] < 0 ? in : out).push_back(corner[c]);
          if (in.empty() || out.empty()) continue;
          Vec3 inside = Vec3::Zero(), outside = Vec3::Zero();
          for (int64_t g : in) inside += position(g) / static_cast<double>(in.size());
          for (int64_t g : out) outside += position(g) / static_cast<double>(out.size());
          const Vec3 outward = outside - inside;
          if (in.size() == 1 || out.size() == 1) {
            const int64_t lone = in.size() == 1 ? in[0] : out[0];
            const auto& others = in.size() == 1 ? out : in;
            emit(crossing(lone, others[0]), crossing(lone, others[1]), crossing(lone, others[2]), outward);
          } else {
            // Quad a0-b0, a0-b1, a1-b1, a1-b0 around the tetrahedron.
            const int p0 = crossing(in[0], out[0]), p1 = crossing(in[0], out[1]);
            const int p2 = crossing(in[1], out[1]), p3 = crossing(in[1], out[0]);
            emit(p0, p1, p2, outward);
            emit(p0, p2, p3, outward);
          }
        }
      }
  return mesh;
}

double capsule(const Vec3& p, const Vec3& a, const Vec3& b, double r)
{
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm() - r;
}

double yShape(const Vec3& p, double length, double r, double armAngle)
{
  const Vec3 o = Vec3::Zero();
  const Vec3 left(-length * std::sin(armAngle), 0, length * std::cos(armAngle));
  const Vec3 right(length * std::sin(armAngle), 0, length * std::cos(armAngle));
  return std::min({capsule(p, Vec3(0, 0, -length), o, r), capsule(p, o, left, r), capsule(p, o, right, r)});
}

}  // namespace spira::test
