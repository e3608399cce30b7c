#include "spira/skeleton/curve_skeleton.h"

#include <algorithm>
#include <utility>

#include "spira/base/error.h"
#include "spira/mesh/union_find.h"

namespace spira {

namespace {

std::vector<std::array<int, 2>> cleanEdges(const std::vector<std::array<int, 2>>& edges, size_t nodeCount)
{
  std::vector<std::array<int, 2>> out;
  out.reserve(edges.size());
  for (auto e : edges) {
    if (e[0] < 0 || e[1] < 0 || static_cast<size_t>(e[0]) >= nodeCount ||
        static_cast<size_t>(e[1]) >= nodeCount)
      throw InternalError("skeleton edge (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) +
                          ") uses a node that does not exist");
    if (e[0] == e[1]) continue;
    if (e[0] > e[1]) std::swap(e[0], e[1]);
    out.push_back(e);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Incident edges per node, as (edge index, other node).
using Adjacency = std::vector<std::vector<std::pair<int, int>>>;

Adjacency adjacency(const std::vector<std::array<int, 2>>& edges, size_t nodeCount)
{
  Adjacency adj(nodeCount);
  for (size_t e = 0; e < edges.size(); ++e) {
    adj[edges[e][0]].emplace_back(static_cast<int>(e), edges[e][1]);
    adj[edges[e][1]].emplace_back(static_cast<int>(e), edges[e][0]);
  }
  return adj;
}

// Follows the chain that leaves `from` along edge `edge` through nodes of degree 2 until it
// reaches a node of another degree or comes back to `from`. Marks the edges it uses.
Polyline walk(const SkeletonGraph& g, const Adjacency& adj, int from, int edge, std::vector<char>& used)
{
  Polyline line{g.nodes[from]};
  int node = from;
  while (true) {
    used[edge] = 1;
    const auto& e = g.edges[edge];
    node = e[0] == node ? e[1] : e[0];
    line.push_back(g.nodes[node]);
    if (adj[node].size() != 2 || node == from) break;
    const auto& next = adj[node][0].first == edge ? adj[node][1] : adj[node][0];
    if (used[next.first]) break;
    edge = next.first;
  }
  return line;
}

bool risesMonotonically(const Polyline& line, double tolerance)
{
  if (!(line.back().z() - line.front().z() > tolerance)) return false;
  double highest = line.front().z();
  for (const Vec3& p : line) {
    if (highest - p.z() > tolerance) return false;
    highest = std::max(highest, p.z());
  }
  return true;
}

}  // namespace

CurveSkeleton analyseSkeleton(SkeletonGraph graph, double zTolerance)
{
  CurveSkeleton out;
  graph.edges = cleanEdges(graph.edges, graph.nodes.size());
  out.graph = std::move(graph);
  const SkeletonGraph& g = out.graph;
  const Adjacency adj = adjacency(g.edges, g.nodes.size());

  UnionFind sets(g.nodes.size());
  size_t components = g.nodes.size();
  for (const auto& e : g.edges)
    if (sets.unite(e[0], e[1])) --components;
  out.components = components;
  out.loops = g.edges.size() + components - g.nodes.size();

  std::vector<char> used(g.edges.size(), 0);
  for (size_t n = 0; n < g.nodes.size(); ++n) {
    if (adj[n].size() == 1) out.endPoints.push_back(g.nodes[n]);
    if (adj[n].size() >= 3) out.branchPoints.push_back(g.nodes[n]);
  }
  // Branch points first, so that every branch touching one starts there.
  for (const bool fromBranchPoints : {true, false})
    for (size_t n = 0; n < g.nodes.size(); ++n) {
      const size_t degree = adj[n].size();
      if (degree == 2 || degree == 0 || (degree >= 3) != fromBranchPoints) continue;
      for (const auto& [edge, other] : adj[n])
        if (!used[edge]) out.branches.push_back(walk(g, adj, static_cast<int>(n), edge, used));
    }
  // What is left are cycles through nodes of degree 2 only.
  for (size_t e = 0; e < g.edges.size(); ++e)
    if (!used[e]) out.branches.push_back(walk(g, adj, g.edges[e][0], static_cast<int>(e), used));

  if (out.branches.size() == 1 && out.monoBranch() && out.endPoints.size() == 2) {
    Polyline& chain = out.branches.front();
    if (chain.front().z() > chain.back().z()) std::reverse(chain.begin(), chain.end());
    out.monotoneInZ = risesMonotonically(chain, std::max(0.0, zTolerance));
  }
  return out;
}

}  // namespace spira
