#include "spira/mesh/ray_bvh.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace spira {
namespace {

constexpr int kLeafSize = 4;

// Möller-Trumbore, two-sided. The barycentric tolerance keeps edges and corners inside.
double rayTriangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c)
{
  constexpr double kEdgeSlack = 1e-9;
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  if (det == 0.0 || !std::isfinite(det)) return -1.0;
  const double inv = 1.0 / det;
  const Vec3 s = o - a;
  const double u = s.dot(p) * inv;
  if (u < -kEdgeSlack || u > 1.0 + kEdgeSlack) return -1.0;
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < -kEdgeSlack || u + v > 1.0 + kEdgeSlack) return -1.0;
  return e2.dot(q) * inv;
}

// Entry distance of the ray into the box, or infinity when it misses within [0, maxT].
double rayBox(const Vec3& o, const Vec3& invD, const BoundingBox& box, double maxT)
{
  double lo = 0.0, hi = maxT;
  for (int k = 0; k < 3; ++k) {
    // A ray parallel to the slab (a zero component, of either sign) meets the box only from within
    // the slab, faces included; the products below would be 0 * inf there.
    if (!std::isfinite(invD[k])) {
      if (o[k] < box.min[k] || o[k] > box.max[k]) return std::numeric_limits<double>::infinity();
      continue;
    }
    double t0 = (box.min[k] - o[k]) * invD[k];
    double t1 = (box.max[k] - o[k]) * invD[k];
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
    if (lo > hi) return std::numeric_limits<double>::infinity();
  }
  return lo;
}

}  // namespace

RayBvh::RayBvh(const TriangleMesh& mesh) : mesh_(mesh)
{
  const size_t nf = mesh.faceCount();
  order_.resize(nf);
  std::iota(order_.begin(), order_.end(), 0);
  std::vector<Vec3> centroids(nf);
  for (size_t f = 0; f < nf; ++f) {
    const Face& t = mesh.faces[f];
    centroids[f] = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
  }
  nodes_.reserve(2 * nf / kLeafSize + 2);
  if (nf > 0) build(0, static_cast<int>(nf), centroids);
}

int RayBvh::build(int first, int count, std::vector<Vec3>& centroids)
{
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  BoundingBox box, centres;
  for (int i = first; i < first + count; ++i) {
    const Face& t = mesh_.faces[static_cast<size_t>(order_[static_cast<size_t>(i)])];
    for (int k = 0; k < 3; ++k) box.extend(mesh_.vertices[static_cast<size_t>(t[k])]);
    centres.extend(centroids[static_cast<size_t>(order_[static_cast<size_t>(i)])]);
  }
  nodes_[static_cast<size_t>(index)].box = box;
  if (count <= kLeafSize) {
    nodes_[static_cast<size_t>(index)].first = first;
    nodes_[static_cast<size_t>(index)].count = count;
    return index;
  }
  int axis = 0;
  const Vec3 extent = centres.size();
  if (extent.y() > extent[axis]) axis = 1;
  if (extent.z() > extent[axis]) axis = 2;
  const int half = count / 2;
  auto begin = order_.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [&](int a, int b) {
    return centroids[static_cast<size_t>(a)][axis] < centroids[static_cast<size_t>(b)][axis];
  });
  build(first, half, centroids);
  const int right = build(first + half, count - half, centroids);
  nodes_[static_cast<size_t>(index)].right = right;
  return index;
}

RayHit RayBvh::firstHit(const Vec3& origin, const Vec3& direction, double minDistance, double maxDistance,
                        int skipFace) const
{
  RayHit hit;
  if (nodes_.empty()) return hit;
  hit.distance = maxDistance;
  const Vec3 invD = direction.cwiseInverse();
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[static_cast<size_t>(stack[--top])];
    if (rayBox(origin, invD, node.box, hit.distance) > hit.distance) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const int f = order_[static_cast<size_t>(i)];
        if (f == skipFace) continue;
        const Face& t = mesh_.faces[static_cast<size_t>(f)];
        const double d =
            rayTriangle(origin, direction, mesh_.vertices[static_cast<size_t>(t[0])],
                        mesh_.vertices[static_cast<size_t>(t[1])], mesh_.vertices[static_cast<size_t>(t[2])]);
        if (d > minDistance && d < hit.distance) {
          hit.distance = d;
          hit.face = f;
        }
      }
      continue;
    }
    const int self = static_cast<int>(&node - nodes_.data());
    stack[top++] = node.right;
    stack[top++] = self + 1;
  }
  if (hit.face < 0) hit.distance = std::numeric_limits<double>::infinity();
  return hit;
}

}  // namespace spira
