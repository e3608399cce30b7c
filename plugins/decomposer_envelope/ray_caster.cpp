#include "ray_caster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace spira {

namespace {

// Entry parameter of the ray into the box (slab test), infinity when it misses within [0, tMax].
double boxEntry(const BoundingBox& box, const Vec3& origin, const Vec3& inverse, double tMax)
{
  double t0 = 0.0, t1 = tMax;
  for (int a = 0; a < 3; ++a) {
    double n = (box.min[a] - origin[a]) * inverse[a];
    double f = (box.max[a] - origin[a]) * inverse[a];
    if (std::isnan(n) || std::isnan(f)) {
      // Ray parallel to the slab and on its boundary plane (0 * inf): inside if within the slab.
      if (origin[a] < box.min[a] || origin[a] > box.max[a]) return std::numeric_limits<double>::infinity();
      continue;
    }
    if (n > f) std::swap(n, f);
    t0 = std::max(t0, n);
    t1 = std::min(t1, f);
    if (t0 > t1) return std::numeric_limits<double>::infinity();
  }
  return t0;
}

// Möller-Trumbore, with a little slack on the barycentric bounds so that a ray through a shared
// edge or vertex is caught by at least one of the faces around it.
bool intersect(const std::array<Vec3, 3>& tri, const Vec3& origin, const Vec3& dir, double& t, double& u,
               double& v)
{
  constexpr double kSlack = 1e-10;
  const Vec3 e1 = tri[1] - tri[0], e2 = tri[2] - tri[0];
  const Vec3 p = dir.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-300) return false;
  const double inv = 1.0 / det;
  const Vec3 s = origin - tri[0];
  u = s.dot(p) * inv;
  if (u < -kSlack || u > 1 + kSlack) return false;
  const Vec3 q = s.cross(e1);
  v = dir.dot(q) * inv;
  if (v < -kSlack || u + v > 1 + kSlack) return false;
  t = e2.dot(q) * inv;
  return true;
}

}  // namespace

RayCaster::RayCaster(const TriangleMesh& mesh)
{
  triangles_.reserve(mesh.faceCount());
  std::vector<BoundingBox> boxes;
  boxes.reserve(mesh.faceCount());
  for (const Face& f : mesh.faces) {
    triangles_.push_back({mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]});
    BoundingBox b;
    for (const Vec3& p : triangles_.back()) b.extend(p);
    boxes.push_back(b);
  }
  tree_ = BvhTree(boxes, {});
}

std::optional<SurfacePoint> RayCaster::nearest(const Vec3& origin, const Vec3& direction, double tMax) const
{
  const Vec3 inverse = direction.cwiseInverse();
  double best = tMax;
  int bestFace = -1;
  double bestU = 0.0, bestV = 0.0;
  tree_.nearest([&](const BvhTree::Node& node) { return boxEntry(node.box, origin, inverse, best); },
                [&](uint32_t face, double& bound) {
                  double t, u, v;
                  if (!intersect(triangles_[face], origin, direction, t, u, v)) return;
                  if (t < 0.0 || t > bound) return;
                  if (bestFace >= 0 && t == bound && static_cast<int>(face) > bestFace) return;
                  bound = t;
                  bestFace = static_cast<int>(face);
                  bestU = u;
                  bestV = v;
                },
                best);
  if (bestFace < 0) return std::nullopt;
  SurfacePoint hit;
  hit.face = bestFace;
  const double u = std::clamp(bestU, 0.0, 1.0), v = std::clamp(bestV, 0.0, 1.0 - u);
  hit.bary = Vec3(1.0 - u - v, u, v);
  hit.position = origin + best * direction;
  return hit;
}

}  // namespace spira
