#include "spira/skeleton/skeleton_pruning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace spira {

namespace {

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

struct Spur {
  std::vector<int> edges;  // indices into the live edge list
  std::vector<int> nodes;  // the spur's nodes except its branch point
  double length = 0.0;
  int junction = -1;
};

}  // namespace

double distanceToSurface(const TriangleMesh& mesh, const Vec3& p)
{
  double best = std::numeric_limits<double>::infinity();
  for (const Face& f : mesh.faces) {
    const Vec3 q = closestOnTriangle(p, mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]);
    best = std::min(best, (q - p).squaredNorm());
  }
  return std::sqrt(best);
}

size_t pruneSpurs(SkeletonGraph& graph, const TriangleMesh& mesh)
{
  std::vector<std::array<int, 2>> edges = graph.edges;
  std::map<int, double> radius;  // distance to the surface per branch point, computed once
  size_t removed = 0;
  while (true) {
    std::vector<std::vector<std::pair<int, int>>> adj(graph.nodes.size());  // (edge, other node)
    for (size_t e = 0; e < edges.size(); ++e) {
      adj[edges[e][0]].emplace_back(static_cast<int>(e), edges[e][1]);
      adj[edges[e][1]].emplace_back(static_cast<int>(e), edges[e][0]);
    }
    std::optional<Spur> shortest;
    for (size_t start = 0; start < adj.size(); ++start) {
      if (adj[start].size() != 1) continue;
      Spur spur;
      int node = static_cast<int>(start), edge = adj[start][0].first;
      while (true) {
        spur.nodes.push_back(node);
        spur.edges.push_back(edge);
        const int next = edges[edge][0] == node ? edges[edge][1] : edges[edge][0];
        spur.length += (graph.nodes[next] - graph.nodes[node]).norm();
        node = next;
        if (adj[node].size() != 2) break;
        edge = adj[node][0].first == edge ? adj[node][1].first : adj[node][0].first;
      }
      if (adj[node].size() < 3) continue;  // the whole component is one chain: no spur
      spur.junction = node;
      auto r = radius.find(node);
      if (r == radius.end()) r = radius.emplace(node, distanceToSurface(mesh, graph.nodes[node])).first;
      if (spur.length < r->second && (!shortest || spur.length < shortest->length))
        shortest = std::move(spur);
    }
    if (!shortest) break;
    std::vector<char> drop(edges.size(), 0);
    for (int e : shortest->edges) drop[e] = 1;
    std::vector<std::array<int, 2>> kept;
    for (size_t e = 0; e < edges.size(); ++e)
      if (!drop[e]) kept.push_back(edges[e]);
    edges = std::move(kept);
    ++removed;
  }
  if (!removed) return 0;

  // Renumber the nodes that still have edges.
  std::vector<int> newIndex(graph.nodes.size(), -1);
  for (const auto& e : edges) newIndex[e[0]] = newIndex[e[1]] = 0;
  SkeletonGraph out;
  for (size_t n = 0; n < graph.nodes.size(); ++n)
    if (newIndex[n] == 0) {
      newIndex[n] = static_cast<int>(out.nodes.size());
      out.nodes.push_back(graph.nodes[n]);
    }
  for (const auto& e : edges) out.edges.push_back({newIndex[e[0]], newIndex[e[1]]});
  graph = std::move(out);
  return removed;
}

}  // namespace spira
