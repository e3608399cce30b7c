#include "spira/mesh/triangle_mesh.h"

#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "spira/mesh/edge_table.h"

namespace spira {

namespace {

// Below this many elements the TBB task overhead costs more than the loop.
constexpr size_t kParallelGrain = 1 << 15;

}  // namespace

BoundingBox finiteBounds(const Vec3* points, size_t count)
{
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, count, kParallelGrain), BoundingBox(),
      [&](const tbb::blocked_range<size_t>& r, BoundingBox box) {
        for (size_t i = r.begin(); i != r.end(); ++i)
          if (points[i].allFinite()) box.extend(points[i]);
        return box;
      },
      [](BoundingBox a, const BoundingBox& b) {
        if (!b.empty()) {
          a.extend(b.min);
          a.extend(b.max);
        }
        return a;
      });
}

BoundingBox TriangleMesh::bounds() const
{
  // Non-finite vertices are skipped: one NaN would otherwise poison the whole box.
  return finiteBounds(vertices.data(), vertices.size());
}

Vec3 TriangleMesh::faceNormalScaled(size_t f) const
{
  const Face& t = faces[f];
  const Vec3& a = vertices[t[0]];
  return (vertices[t[1]] - a).cross(vertices[t[2]] - a);
}

Vec3 TriangleMesh::faceNormal(size_t f) const
{
  const Vec3 n = faceNormalScaled(f);
  const double len = n.norm();
  return len > 0.0 ? Vec3(n / len) : Vec3::Zero();
}

double TriangleMesh::faceArea(size_t f) const
{
  return 0.5 * faceNormalScaled(f).norm();
}

// Sums use parallel_deterministic_reduce: the same chunks added in the same order whatever the
// thread count, so a floating-point sum comes out the same to the last bit on every run.
double TriangleMesh::area() const
{
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<size_t>(0, faces.size(), kParallelGrain), 0.0,
      [&](const tbb::blocked_range<size_t>& r, double sum) {
        for (size_t f = r.begin(); f != r.end(); ++f) sum += faceArea(f);
        return sum;
      },
      [](double a, double b) { return a + b; });
}

double TriangleMesh::meanEdgeLength() const
{
  const EdgeTable table = buildEdgeTable(*this);
  const size_t ne = table.edgeCount();
  if (ne == 0) return 0.0;
  const double sum = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<size_t>(0, ne, kParallelGrain), 0.0,
      [&](const tbb::blocked_range<size_t>& r, double s) {
        for (size_t e = r.begin(); e != r.end(); ++e) {
          const int h = table.firstHalfEdge(e);
          s += (vertices[halfEdgeTo(*this, h)] - vertices[halfEdgeFrom(*this, h)]).norm();
        }
        return s;
      },
      [](double a, double b) { return a + b; });
  return sum / static_cast<double>(ne);
}

std::vector<Vec3> TriangleMesh::vertexNormals() const
{
  std::vector<Vec3> normals(vertices.size(), Vec3::Zero());
  for (size_t f = 0; f < faces.size(); ++f) {
    // The scaled normal's length is twice the area: that is the area weighting.
    const Vec3 n = faceNormalScaled(f);
    if (!n.allFinite()) continue;
    for (int v : faces[f]) normals[v] += n;
  }
  for (Vec3& n : normals) {
    const double len = n.norm();
    n = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
  }
  return normals;
}

void TriangleMesh::transform(const Transform& T)
{
  tbb::parallel_for(tbb::blocked_range<size_t>(0, vertices.size(), kParallelGrain),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i) vertices[i] = T * vertices[i];
                    });
  // A reflection would turn every face inside out; keep the normals pointing outwards.
  if (T.linear().determinant() < 0.0)
    for (Face& f : faces) std::swap(f[1], f[2]);
}

TriangleMesh TriangleMesh::transformed(const Transform& T) const
{
  TriangleMesh m = *this;
  m.transform(T);
  return m;
}

}  // namespace spira
