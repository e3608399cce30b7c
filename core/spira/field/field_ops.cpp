#include "spira/field/field_ops.h"

#include <cmath>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "spira/base/error.h"

namespace spira {
namespace {

void checkFace(const TriangleMesh& mesh, const std::vector<double>& values, int face)
{
  if (face < 0 || size_t(face) >= mesh.faces.size())
    throw InputError("face " + std::to_string(face) + " does not exist (the mesh has " +
                         std::to_string(mesh.faces.size()) + " faces)",
                     "pass a face id of this mesh");
  if (values.size() != mesh.vertices.size())
    throw InputError("the field has " + std::to_string(values.size()) + " values but the mesh has " +
                         std::to_string(mesh.vertices.size()) + " vertices",
                     "recompute the field for this mesh");
}

Vec3 gradientOn(const TriangleMesh& mesh, const std::vector<double>& values, int face)
{
  const Face& t = mesh.faces[face];
  const Vec3 &p0 = mesh.vertices[t[0]], &p1 = mesh.vertices[t[1]], &p2 = mesh.vertices[t[2]];
  const Vec3 normal = (p1 - p0).cross(p2 - p0);  // length 2 A_f
  const double twiceArea2 = normal.squaredNorm();
  if (!(twiceArea2 > 0.0)) return Vec3::Zero();
  // grad u = (1 / 2A) sum_i u_i (N x e_i), e_i the edge opposite vertex i, counter-clockwise.
  const Vec3 sum = values[t[0]] * (p2 - p1) + values[t[1]] * (p0 - p2) + values[t[2]] * (p1 - p0);
  return normal.cross(sum) / twiceArea2;
}

}  // namespace

int argmaxVertex(const std::vector<double>& values)
{
  int best = -1;
  for (size_t v = 0; v < values.size(); ++v)
    if (std::isfinite(values[v]) && (best < 0 || values[v] > values[best])) best = int(v);
  return best;
}

double interpolateField(const TriangleMesh& mesh, const std::vector<double>& values, int face,
                        const Vec3& barycentric)
{
  checkFace(mesh, values, face);
  const Face& t = mesh.faces[face];
  return barycentric[0] * values[t[0]] + barycentric[1] * values[t[1]] + barycentric[2] * values[t[2]];
}

Vec3 faceGradient(const TriangleMesh& mesh, const std::vector<double>& values, int face)
{
  checkFace(mesh, values, face);
  return gradientOn(mesh, values, face);
}

std::vector<Vec3> faceGradients(const TriangleMesh& mesh, const std::vector<double>& values)
{
  if (mesh.faces.empty()) return {};
  checkFace(mesh, values, 0);
  std::vector<Vec3> out(mesh.faces.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.faces.size(), 8192),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t f = r.begin(); f < r.end(); ++f) out[f] = gradientOn(mesh, values, int(f));
                    });
  return out;
}

}  // namespace spira
