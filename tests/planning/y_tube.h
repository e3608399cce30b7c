#pragma once

// A Y-shaped tube made in code for the multi-branch tests: the boundary of a union of capsules
// (a vertical trunk, two arms leaning out at +/- alpha from the top of the trunk, each bending back
// to vertical) meshed by marching tetrahedra on a grid whose bottom plane is z = 0 and top plane
// z = top, so the surface is open there: one base loop, two top loops, no caps to remove.
//
// The crotch (the saddle of any field that grows up the part) is where the two leaning arms meet
// in the plane x = 0: two equal cylinders whose axes cross at O = (0, 0, trunkTop) meet along the
// ellipse y^2 + sin^2(alpha) (z - trunkTop)^2 = r^2, whose top, (0, 0, trunkTop + r / sin(alpha)),
// is the saddle.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira::test {

// The vertex where the surface crosses grid edge (a, b); `pa` belongs to `a`. Keyed by the
// ordered pair, so both tetrahedra of an edge share it.
template <class Map>
int crossVertex(std::int64_t a, const Vec3& pa, std::int64_t b, const Vec3& pb, std::int64_t stride,
                const std::vector<double>& value, Map& edgeVertex, TriangleMesh& m)
{
  const std::int64_t key = std::max(a, b) * stride + std::min(a, b);
  const auto it = edgeVertex.find(key);
  if (it != edgeVertex.end()) return it->second;
  const double va = value[static_cast<size_t>(a)], vb = value[static_cast<size_t>(b)];
  const double t = va / (va - vb);
  m.vertices.push_back((1.0 - t) * pa + t * pb);
  const int v = static_cast<int>(m.vertices.size()) - 1;
  edgeVertex.emplace(key, v);
  return v;
}

template <class Cross>
void tetrahedron(const std::array<std::int64_t, 4>& ids, const std::array<Vec3, 4>& pos,
                 const std::vector<double>& value, Cross& cross, TriangleMesh& m)
{
  std::vector<int> in, out;
  for (int q = 0; q < 4; ++q) (value[static_cast<size_t>(ids[q])] < 0 ? in : out).push_back(q);
  if (in.empty() || out.empty()) return;
  Vec3 cin = Vec3::Zero(), cout = Vec3::Zero();
  for (int q : in) cin += pos[static_cast<size_t>(q)] / static_cast<double>(in.size());
  for (int q : out) cout += pos[static_cast<size_t>(q)] / static_cast<double>(out.size());
  auto emit = [&](int a, int b, int c) {
    const Vec3 n = (m.vertices[b] - m.vertices[a]).cross(m.vertices[c] - m.vertices[a]);
    if (n.dot(cout - cin) < 0) std::swap(b, c);  // outward: towards the outside corners
    m.faces.push_back({a, b, c});
  };
  auto x = [&](int p, int q) {
    return cross(ids[static_cast<size_t>(p)], pos[static_cast<size_t>(p)], ids[static_cast<size_t>(q)],
                 pos[static_cast<size_t>(q)]);
  };
  if (in.size() == 1 || out.size() == 1) {
    const bool lone = in.size() == 1;
    const int a = lone ? in[0] : out[0];
    const std::vector<int>& others = lone ? out : in;
    emit(x(a, others[0]), x(a, others[1]), x(a, others[2]));
  } else {
    const int p0 = x(in[0], out[0]), p1 = x(in[0], out[1]), p2 = x(in[1], out[1]), p3 = x(in[1], out[0]);
    emit(p0, p1, p2);
    emit(p0, p2, p3);
  }
}

// The surface implicit(p) = 0 (negative inside) over the grid box [lo, lo + (nx, ny, nz) * cell]
// with z spacing dz, by marching tetrahedra: six tetrahedra around each cube's diagonal (Kuhn),
// consistent between neighbouring cubes, so the surface is a manifold with shared vertices, its
// faces oriented outwards (towards positive values). Where it leaves the box it is open, with its
// free edge on the box's face. Grid values closer to 0 than cell / 10 are pushed to +/- cell / 10
// so no triangle shrinks to a point.
template <class Implicit>
TriangleMesh marchingTetrahedra(const Implicit& implicit, const Vec3& lo, int nx, int ny, int nz, double cell,
                                double dz)
{
  auto at = [&](int i, int j, int k) -> Vec3 { return lo + Vec3(i * cell, j * cell, k * dz); };
  auto id = [&](int i, int j, int k) { return static_cast<std::int64_t>((k * (ny + 1) + j) * (nx + 1) + i); };
  std::vector<double> value(static_cast<size_t>((nx + 1) * (ny + 1) * (nz + 1)));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        double v = implicit(at(i, j, k));
        if (std::abs(v) < 0.1 * cell) v = v < 0 ? -0.1 * cell : 0.1 * cell;
        value[static_cast<size_t>(id(i, j, k))] = v;
      }
  TriangleMesh m;
  std::unordered_map<std::int64_t, int> edgeVertex;
  const auto stride = static_cast<std::int64_t>(value.size());
  auto cross = [&](std::int64_t a, const Vec3& pa, std::int64_t b, const Vec3& pb) {
    return crossVertex(a, pa, b, pb, stride, value, edgeVertex, m);
  };
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& perm : perms) {
          std::array<int, 3> c{i, j, k};
          std::array<std::int64_t, 4> ids;
          std::array<Vec3, 4> pos;
          ids[0] = id(c[0], c[1], c[2]);
          pos[0] = at(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[static_cast<size_t>(perm[s])];
            ids[static_cast<size_t>(s + 1)] = id(c[0], c[1], c[2]);
            pos[static_cast<size_t>(s + 1)] = at(c[0], c[1], c[2]);
          }
          tetrahedron(ids, pos, value, cross, m);
        }
  return m;
}

// Distance from p to the segment [a, b].
inline double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 d = b - a;
  const Vec3 pa = p - a;
  const double t = std::clamp(pa.dot(d) / d.squaredNorm(), 0.0, 1.0);
  const Vec3 foot = a + t * d;
  return (p - foot).norm();
}

struct YTube {
  double radius = 12.0;
  double trunkTop = 30.0;    // z of O, where the arms leave the trunk's axis
  double alpha = 0.6108652;  // 35 degrees: lean of the arms from vertical
  double armLength = 40.0;   // along the leaning axis, before the arm turns vertical
  double top = 108.0;        // the grid's top plane: where the arms are cut open
  double cell = 1.2;         // grid spacing, mm
  bool bothArms = true;      // false: the arm at +x only (a bent, mono-branch tube)
  // Length of the arms' vertical parts; below top - radius the arms end in round caps inside the
  // grid, so the part is closed (one free edge, the base) and each arm has its own top.
  double armRise = 1000.0;
  double rightArmRise = -1.0;  // the arm at +x only, when >= 0 (one open arm, one capped)

  Vec3 origin() const { return Vec3(0, 0, trunkTop); }
  Vec3 bend(int side) const
  {
    return origin() + armLength * Vec3(side * std::sin(alpha), 0.0, std::cos(alpha));
  }
  double rise(int side) const { return side > 0 && rightArmRise >= 0 ? rightArmRise : armRise; }
  Vec3 armTip(int side) const { return bend(side) + Vec3(0.0, 0.0, rise(side) + radius); }
  Vec3 saddle() const { return Vec3(0, 0, trunkTop + radius / std::sin(alpha)); }

  // Signed distance to the union of the capsules (negative inside).
  double implicit(const Vec3& p) const
  {
    const Vec3 o = origin();
    const Vec3 bottom = o - Vec3(0.0, 0.0, 1000.0);
    double d = segmentDistance(p, bottom, o);
    for (int side : {-1, 1}) {
      if (side < 0 && !bothArms) continue;
      const Vec3 b = bend(side);
      const Vec3 up = b + Vec3(0.0, 0.0, rise(side));
      d = std::min(d, segmentDistance(p, o, b));
      d = std::min(d, segmentDistance(p, b, up));
    }
    return d - radius;
  }

  TriangleMesh mesh() const
  {
    const double xMax = armLength * std::sin(alpha) + radius + 3.0 * cell;
    const int nx = static_cast<int>(std::ceil(2.0 * xMax / cell));
    const int ny = static_cast<int>(std::ceil(2.0 * (radius + 3.0 * cell) / cell));
    const int nz = static_cast<int>(std::lround(top / cell));
    const Vec3 lo(-0.5 * nx * cell, -0.5 * ny * cell, 0.0);
    return marchingTetrahedra([this](const Vec3& p) { return implicit(p); }, lo, nx, ny, nz, cell, top / nz);
  }
};

}  // namespace spira::test
