#include "spira/mesh/boundary_loops.h"

#include <algorithm>
#include <limits>

namespace spira {

namespace {

// The corner of vertex v in the face of half-edge h (v is one of h's ends).
int cornerAt(const TriangleMesh& mesh, int h, int v)
{
  return halfEdgeFrom(mesh, h) == v ? h : 3 * (h / 3) + (h % 3 + 1) % 3;
}

void measure(const TriangleMesh& mesh, BoundaryLoop& loop)
{
  loop.zMin = std::numeric_limits<double>::infinity();
  loop.zMax = -std::numeric_limits<double>::infinity();
  loop.length = 0.0;
  const size_t n = loop.vertices.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& p = mesh.vertices[loop.vertices[i]];
    loop.zMin = std::min(loop.zMin, p.z());
    loop.zMax = std::max(loop.zMax, p.z());
    if (i + 1 < n || loop.closed) loop.length += (mesh.vertices[loop.vertices[(i + 1) % n]] - p).norm();
  }
}

}  // namespace

std::vector<BoundaryLoop> extractBoundaryLoops(const TriangleMesh& mesh, const EdgeTable& edges,
                                               const VertexFans& fans)
{
  std::vector<int> boundary;  // the one half-edge of every boundary edge, in edge order
  for (size_t e = 0; e < edges.edgeCount(); ++e)
    if (edges.faceCountOf(e) == 1) boundary.push_back(edges.firstHalfEdge(e));
  if (boundary.empty()) return {};

  // Boundary edges at each vertex (both ends).
  const size_t nv = mesh.vertexCount();
  std::vector<int> offset(nv + 1, 0);
  for (int h : boundary) {
    ++offset[halfEdgeFrom(mesh, h) + 1];
    ++offset[halfEdgeTo(mesh, h) + 1];
  }
  for (size_t v = 0; v < nv; ++v) offset[v + 1] += offset[v];
  std::vector<int> incident(static_cast<size_t>(offset[nv]));
  {
    std::vector<int> cursor(offset.begin(), offset.end() - 1);
    for (size_t i = 0; i < boundary.size(); ++i) {
      incident[cursor[halfEdgeFrom(mesh, boundary[i])]++] = static_cast<int>(i);
      incident[cursor[halfEdgeTo(mesh, boundary[i])]++] = static_cast<int>(i);
    }
  }

  std::vector<char> used(boundary.size(), 0);
  std::vector<BoundaryLoop> loops;
  for (size_t s = 0; s < boundary.size(); ++s) {
    if (used[s]) continue;
    used[s] = 1;
    BoundaryLoop loop;
    const int start = halfEdgeFrom(mesh, boundary[s]);
    int cur = halfEdgeTo(mesh, boundary[s]);
    int fan = fans.fanOfCorner[cornerAt(mesh, boundary[s], cur)];
    loop.vertices.push_back(start);
    while (cur != start) {
      loop.vertices.push_back(cur);
      // Prefer the edge leaving cur in the fan we arrived through; then any leaving edge; only
      // then one that runs against the loop (inconsistent orientation).
      int best = -1, bestRank = 4;
      for (int j = offset[cur]; j < offset[cur + 1] && bestRank > 0; ++j) {
        const int i = incident[j];
        if (used[i]) continue;
        const int h = boundary[i];
        const int rank = (halfEdgeFrom(mesh, h) == cur ? 0 : 2) +
                         (fans.fanOfCorner[cornerAt(mesh, h, cur)] == fan ? 0 : 1);
        if (rank < bestRank) {
          bestRank = rank;
          best = i;
        }
      }
      if (best < 0) {
        loop.closed = false;
        break;
      }
      used[best] = 1;
      const int h = boundary[best];
      cur = halfEdgeFrom(mesh, h) == cur ? halfEdgeTo(mesh, h) : halfEdgeFrom(mesh, h);
      fan = fans.fanOfCorner[cornerAt(mesh, h, cur)];
    }
    measure(mesh, loop);
    loops.push_back(std::move(loop));
  }
  std::stable_sort(loops.begin(), loops.end(),
                   [](const BoundaryLoop& a, const BoundaryLoop& b) { return a.zMin < b.zMin; });
  return loops;
}

Vec3 polygonCentroid(const std::vector<Vec3>& points)
{
  Vec3 sum = Vec3::Zero();
  double length = 0.0;
  const size_t n = points.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = points[i];
    const Vec3& b = points[(i + 1) % n];
    const double l = (b - a).norm();
    sum += l * 0.5 * (a + b);
    length += l;
  }
  if (length > 0) return sum / length;
  for (const Vec3& p : points) sum += p;
  return n ? Vec3(sum / static_cast<double>(n)) : Vec3::Zero();
}

Vec3 loopCentroid(const TriangleMesh& mesh, const BoundaryLoop& loop)
{
  std::vector<Vec3> points;
  points.reserve(loop.vertices.size());
  for (int v : loop.vertices) points.push_back(mesh.vertices[static_cast<size_t>(v)]);
  return polygonCentroid(points);
}

}  // namespace spira
