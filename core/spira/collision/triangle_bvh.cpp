#include "spira/collision/triangle_bvh.h"

#include <algorithm>

#include "spira/base/error.h"
#include "spira/collision/bvh_queries.h"

namespace spira {

namespace {

constexpr uint32_t kAllKeys = std::numeric_limits<uint32_t>::max();

// The distance from the query shape's bounding capsule to triangle p is at least this: the triangle
// lies in the sphere about its centroid through its farthest vertex.
auto lowerBound(const TriangleBvh& bvh)
{
  return [&bvh](uint32_t p, const bvh_detail::CapsuleBound& bound) {
    if (!bound.valid) return -std::numeric_limits<double>::infinity();
    const TriangleShape t = bvh.triangle(p);
    const Vec3 c = (t.vertex(0) + t.vertex(1) + t.vertex(2)) / 3.0;
    const double r = std::max({(t.vertex(0) - c).norm(), (t.vertex(1) - c).norm(), (t.vertex(2) - c).norm()});
    return bvh_detail::sphereLowerBound(bound, c, r);
  };
}

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh)
{
  triangles_.reserve(mesh.faces.size());
  std::vector<BoundingBox> boxes;
  boxes.reserve(mesh.faces.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    std::array<Vec3, 3> t;
    BoundingBox box;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.faces[f][k];
      if (v < 0 || static_cast<size_t>(v) >= mesh.vertices.size())
        throw InputError("collision mesh face " + std::to_string(f) + " refers to vertex " +
                             std::to_string(v) + " of " + std::to_string(mesh.vertices.size()),
                         "repair or re-export the mesh");
      if (!mesh.vertices[v].allFinite())
        throw InputError("collision mesh vertex " + std::to_string(v) + " is not a finite point",
                         "repair or re-export the mesh");
      t[k] = mesh.vertices[v];
      box.extend(t[k]);
    }
    triangles_.push_back(t);
    boxes.push_back(box);
  }
  tree_ = BvhTree(boxes, {});
}

bool TriangleBvh::intersects(const ConvexShape& shape, double margin) const
{
  return bvh_detail::anyWithin(
      tree_, shape, margin, kAllKeys, [](uint32_t p) { return p; }, [](uint32_t) { return 0.0; },
      [&](uint32_t p) { return triangle(p); }, lowerBound(*this));
}

NearestHit TriangleBvh::nearest(const ConvexShape& shape, double maxDistance, double slack) const
{
  return bvh_detail::nearestTo(
      tree_, shape, maxDistance, kAllKeys, slack, [](uint32_t p) { return p; }, [](uint32_t) { return 0.0; },
      [&](uint32_t p) { return triangle(p); }, lowerBound(*this));
}

std::vector<size_t> TriangleBvh::within(const ConvexShape& shape, double margin) const
{
  return bvh_detail::allWithin(
      tree_, shape, margin, kAllKeys, [](uint32_t p) { return p; }, [](uint32_t) { return 0.0; },
      [&](uint32_t p) { return triangle(p); }, lowerBound(*this));
}

}  // namespace spira
