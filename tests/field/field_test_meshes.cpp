#include "field/field_test_meshes.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace spira::test {
namespace {

struct Ring {
  double radius, z;
};

// Joins consecutive rings by walking both in angle order (a "zipper"), so rings with different
// vertex counts still give well-shaped triangles. Odd rings are rotated by half a step.
RingMesh stackRings(const std::vector<Ring>& rings, double edge, bool closeWithPole, double poleZ)
{
  RingMesh out;
  std::vector<int> start, count;
  for (size_t i = 0; i < rings.size(); ++i) {
    const int m = std::max(6, int(std::lround(2.0 * M_PI * rings[i].radius / edge)));
    start.push_back(int(out.mesh.vertices.size()));
    count.push_back(m);
    const double offset = (i % 2) * 0.5;
    for (int k = 0; k < m; ++k) {
      const double a = 2.0 * M_PI * (k + offset) / m;
      out.mesh.vertices.emplace_back(rings[i].radius * std::cos(a), rings[i].radius * std::sin(a),
                                     rings[i].z);
    }
  }
  for (size_t i = 0; i + 1 < rings.size(); ++i) {
    const int a = start[i], na = count[i], b = start[i + 1], nb = count[i + 1];
    const double offA = (i % 2) * 0.5, offB = ((i + 1) % 2) * 0.5;
    int ia = 0, ib = 0;
    // Both walks start at angle ~0: the first vertex of ring b may lie before that of ring a.
    while (ia < na || ib < nb) {
      const double nextA = (ia + 1 + offA) / na, nextB = (ib + 1 + offB) / nb;
      const bool advanceA = ib >= nb || (ia < na && nextA < nextB);
      const int a0 = a + ia % na, b0 = b + ib % nb;
      if (advanceA) {
        out.mesh.faces.push_back({a0, a + (ia + 1) % na, b0});
        ++ia;
      } else {
        out.mesh.faces.push_back({a0, b + (ib + 1) % nb, b0});
        ++ib;
      }
    }
  }
  for (int k = 0; k < count.front(); ++k) out.lower.push_back(start.front() + k);
  if (closeWithPole) {
    out.pole = int(out.mesh.vertices.size());
    out.mesh.vertices.emplace_back(0.0, 0.0, poleZ);
    const int a = start.back(), na = count.back();
    for (int k = 0; k < na; ++k) out.mesh.faces.push_back({a + k, a + (k + 1) % na, out.pole});
  } else {
    for (int k = 0; k < count.back(); ++k) out.upper.push_back(start.back() + k);
  }
  return out;
}

}  // namespace

RingMesh tubeMesh(double r, double height, double edge)
{
  return coneMesh(r, r, height, edge);
}

RingMesh coneMesh(double r0, double r1, double height, double edge)
{
  const double slant = std::hypot(height, r1 - r0);
  // Rows of equilateral triangles are sqrt(3)/2 edges apart.
  const int n = std::max(1, int(std::lround(slant / (edge * std::sqrt(3.0) / 2.0))));
  std::vector<Ring> rings;
  for (int i = 0; i <= n; ++i) {
    const double s = double(i) / n;
    rings.push_back({r0 + s * (r1 - r0), s * height});
  }
  return stackRings(rings, edge, false, 0.0);
}

RingMesh domeMesh(double r, double edge)
{
  const int n = std::max(2, int(std::lround(0.5 * M_PI * r / (edge * std::sqrt(3.0) / 2.0))));
  std::vector<Ring> rings;
  for (int i = 0; i < n; ++i) {
    const double polar = 0.5 * M_PI * (1.0 - double(i) / n);
    rings.push_back({r * std::sin(polar), r * std::cos(polar)});
  }
  return stackRings(rings, edge, true, r);
}

RingMesh jitteredDome(double r, double edge, double jitter, unsigned seed)
{
  RingMesh dome = domeMesh(r, edge);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<char> keep(dome.mesh.vertices.size(), 0);
  for (int v : dome.lower) keep[v] = 1;
  keep[dome.pole] = 1;
  for (size_t v = 0; v < dome.mesh.vertices.size(); ++v) {
    if (keep[v]) continue;
    Vec3& p = dome.mesh.vertices[v];
    p += jitter * edge * Vec3(unit(rng), unit(rng), unit(rng));
    p.z() = std::max(p.z(), 0.1 * edge);
    p = r * p.normalized();
  }
  return dome;
}

TriangleMesh jitteredPlane(double half, double edge, double jitter, unsigned seed)
{
  const double rowStep = edge * std::sqrt(3.0) / 2.0;
  const int cols = std::max(2, int(std::lround(2.0 * half / edge)));
  const int rows = std::max(2, int(std::lround(2.0 * half / rowStep)));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  TriangleMesh mesh;
  // Odd rows are shifted by half an edge (a triangular lattice); the side columns stay straight.
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= cols; ++i) {
      const double shift = (j % 2 && i > 0 && i < cols) ? 0.5 : 0.0;
      Vec3 p(-half + 2.0 * half * (i + shift) / cols, -half + 2.0 * half * j / rows, 0.0);
      if (i > 0 && i < cols && j > 0 && j < rows) {
        p.x() += jitter * edge * unit(rng);
        p.y() += jitter * edge * unit(rng);
      }
      mesh.vertices.push_back(p);
    }
  }
  auto id = [cols](int i, int j) { return j * (cols + 1) + i; };
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < cols; ++i) {
      // The diagonal of each cell follows the lattice: towards the shifted row's vertex.
      if (j % 2 == 0) {
        mesh.faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        mesh.faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        mesh.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        mesh.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  }
  return mesh;
}

}  // namespace spira::test
