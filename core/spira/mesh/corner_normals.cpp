#include "spira/mesh/corner_normals.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "spira/mesh/vertex_corners.h"

namespace spira {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The face's interior angle at its corner k.
double cornerAngle(const TriangleMesh& mesh, const Face& f, int k)
{
  const Vec3& p = mesh.vertices[f[k]];
  const Vec3 a = mesh.vertices[f[(k + 1) % 3]] - p, b = mesh.vertices[f[(k + 2) % 3]] - p;
  const double la = a.norm(), lb = b.norm();
  if (!(la > 0.0) || !(lb > 0.0)) return 0.0;
  return std::acos(std::clamp(a.dot(b) / (la * lb), -1.0, 1.0));
}

}  // namespace

std::vector<Vec3> cornerNormals(const TriangleMesh& mesh, double creaseAngleDeg)
{
  const size_t faceCount = mesh.faces.size();
  std::vector<Vec3> unit(faceCount, Vec3::Zero());
  std::vector<double> angle(3 * faceCount, 0.0);
  tbb::parallel_for(size_t(0), faceCount, [&](size_t f) {
    const Vec3 n = mesh.faceNormalScaled(f);
    const double len = n.norm();
    if (!(len > 0.0) || !n.allFinite()) return;
    unit[f] = n / len;
    for (int k = 0; k < 3; ++k) angle[3 * f + k] = cornerAngle(mesh, mesh.faces[f], k);
  });

  const VertexCorners vc = buildVertexCorners(mesh);
  const double cosCrease = std::cos(creaseAngleDeg * kPi / 180.0);
  std::vector<Vec3> out(3 * faceCount, Vec3::Zero());
  tbb::parallel_for(size_t(0), mesh.vertices.size(), [&](size_t v) {
    const int* begin = vc.corners.data() + vc.offset[v];
    const int* end = vc.corners.data() + vc.offset[v + 1];
    Vec3 all = Vec3::Zero();
    for (const int* c = begin; c != end; ++c) all += angle[size_t(*c)] * unit[size_t(*c / 3)];
    for (const int* c = begin; c != end; ++c) {
      const Vec3& own = unit[size_t(*c / 3)];
      if (own.isZero()) {
        out[size_t(*c)] = all.norm() > 0.0 ? Vec3(all.normalized()) : Vec3::Zero();
        continue;
      }
      Vec3 sum = Vec3::Zero();
      for (const int* o = begin; o != end; ++o) {
        const Vec3& other = unit[size_t(*o / 3)];
        if (other.dot(own) >= cosCrease) sum += angle[size_t(*o)] * other;
      }
      out[size_t(*c)] = sum.norm() > 0.0 ? Vec3(sum.normalized()) : own;
    }
  });
  return out;
}

}  // namespace spira
