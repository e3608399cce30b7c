#pragma once

#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// A point on a triangle mesh: inside face `face`, at barycentric weights `bary` of the face's
// corners faces[face][0..2] (non-negative, summing to 1). Per-vertex values (normals, field,
// colours) are interpolated at it linearly, as a P1 finite element would.
struct SurfacePoint {
  Vec3 position = Vec3::Zero();
  int face = -1;
  Vec3 bary = Vec3::Zero();
};

// The linear interpolation of the per-vertex `values` at `p`.
double interpolateAt(const TriangleMesh& mesh, const SurfacePoint& p, const std::vector<double>& values);
Vec3 interpolateAt(const TriangleMesh& mesh, const SurfacePoint& p, const std::vector<Vec3>& values);

// The unit surface normal at `p`: its face's corner normals (from cornerNormals(mesh)) interpolated
// and normalised, so it varies smoothly across faces and stops at feature edges. Falls back to the
// face normal where the interpolated normals cancel out (a knife edge).
Vec3 surfaceNormalAt(const TriangleMesh& mesh, const std::vector<Vec3>& cornerNormals, const SurfacePoint& p);

// The point of face `face` closest to `q` (q itself when it lies on the face, as a ray's hit does).
SurfacePoint closestPointOnFace(const TriangleMesh& mesh, int face, const Vec3& q);

// The surface point of `mesh` closest to `q` (brute force over faces: meant for a few queries).
SurfacePoint closestSurfacePoint(const TriangleMesh& mesh, const Vec3& q);

}  // namespace spira
