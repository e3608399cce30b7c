#include "spira/mesh/wall_skin.h"

#include <algorithm>
#include <map>
#include <queue>
#include <set>
#include <utility>

#include "spira/mesh/edge_table.h"
#include "spira/mesh/union_find.h"

namespace spira {
namespace {

struct Patches {
  std::vector<int> of;  // per face: its patch
  std::vector<double> area;
  std::vector<std::uint8_t> wall;
  std::set<std::pair<int, int>> borders;  // patches sharing an edge, both orders
  size_t count() const { return area.size(); }
};

// Faces joined across two-face edges when both are wall faces or both are not.
Patches findPatches(const TriangleMesh& mesh, const std::vector<std::uint8_t>& wall)
{
  const size_t nf = mesh.faceCount();
  const EdgeTable edges = buildEdgeTable(mesh);
  UnionFind uf(nf);
  std::vector<std::pair<int, int>> pairs;
  for (size_t e = 0; e < edges.edgeCount(); ++e) {
    if (edges.faceCountOf(e) != 2) continue;
    const int a = edges.halfEdges[edges.edgeStart[e]] / 3, b = edges.halfEdges[edges.edgeStart[e] + 1] / 3;
    if (wall[static_cast<size_t>(a)] == wall[static_cast<size_t>(b)])
      uf.unite(a, b);
    else
      pairs.emplace_back(a, b);
  }
  Patches p;
  p.of.assign(nf, -1);
  std::vector<int> index(nf, -1);
  for (size_t f = 0; f < nf; ++f) {
    const size_t root = static_cast<size_t>(uf.find(static_cast<int>(f)));
    if (index[root] < 0) {
      index[root] = static_cast<int>(p.area.size());
      p.area.push_back(0.0);
      p.wall.push_back(wall[f]);
    }
    p.of[f] = index[root];
    p.area[static_cast<size_t>(index[root])] += mesh.faceArea(f);
  }
  for (const auto& [a, b] : pairs) {
    const int pa = p.of[static_cast<size_t>(a)], pb = p.of[static_cast<size_t>(b)];
    p.borders.insert({pa, pb});
    p.borders.insert({pb, pa});
  }
  return p;
}

// Per wall patch, the wall patch most of its ray area lands on.
std::vector<int> oppositePatches(const TriangleMesh& mesh, const Patches& p, const std::vector<int>& hitFace)
{
  std::map<std::pair<int, int>, double> votes;
  for (size_t f = 0; f < hitFace.size(); ++f) {
    const int g = hitFace[f];
    const int from = p.of[f];
    if (g < 0 || !p.wall[static_cast<size_t>(from)]) continue;
    const int to = p.of[static_cast<size_t>(g)];
    if (p.wall[static_cast<size_t>(to)] && to != from) votes[{from, to}] += mesh.faceArea(f);
  }
  std::vector<int> opposite(p.count(), -1);
  std::vector<double> best(p.count(), 0.0);
  for (const auto& [pair, area] : votes) {
    if (area <= best[static_cast<size_t>(pair.first)]) continue;
    best[static_cast<size_t>(pair.first)] = area;
    opposite[static_cast<size_t>(pair.first)] = pair.second;
  }
  return opposite;
}

// Two sides (0, 1) by alternating across the wall, largest patch first so it takes side 0.
std::vector<int> sidesAcrossWall(const Patches& p, const std::vector<int>& opposite)
{
  std::vector<std::vector<int>> links(p.count());
  for (size_t a = 0; a < p.count(); ++a) {
    if (opposite[a] < 0) continue;
    links[a].push_back(opposite[a]);
    links[static_cast<size_t>(opposite[a])].push_back(static_cast<int>(a));
  }
  std::vector<int> order(p.count());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return p.area[static_cast<size_t>(a)] > p.area[static_cast<size_t>(b)];
  });
  std::vector<int> side(p.count(), -1);
  for (int start : order) {
    if (side[static_cast<size_t>(start)] >= 0 || links[static_cast<size_t>(start)].empty()) continue;
    side[static_cast<size_t>(start)] = 0;
    std::queue<int> todo;
    todo.push(start);
    while (!todo.empty()) {
      const int a = todo.front();
      todo.pop();
      for (int b : links[static_cast<size_t>(a)]) {
        if (side[static_cast<size_t>(b)] >= 0) continue;
        side[static_cast<size_t>(b)] = 1 - side[static_cast<size_t>(a)];
        todo.push(b);
      }
    }
  }
  return side;
}

// Patches without a side join the one side all their sided neighbours are on; a few passes reach
// patches bordering only other such patches (a ledge next to a grazed face).
void joinBorderingSides(const Patches& p, std::vector<int>& side)
{
  for (int pass = 0; pass < 4; ++pass) {
    std::vector<int> seen(p.count(), -1);  // -1 none, 0/1 one side, 2 both
    for (const auto& [a, b] : p.borders) {
      const int s = side[static_cast<size_t>(b)];
      if (side[static_cast<size_t>(a)] >= 0 || s < 0) continue;
      int& v = seen[static_cast<size_t>(a)];
      v = v < 0 ? s : (v == s ? v : 2);
    }
    bool changed = false;
    for (size_t a = 0; a < p.count(); ++a)
      if (side[a] < 0 && (seen[a] == 0 || seen[a] == 1)) {
        side[a] = seen[a];
        changed = true;
      }
    if (!changed) break;
  }
}

}  // namespace

std::vector<std::uint8_t> outerSkin(const TriangleMesh& mesh, const std::vector<std::uint8_t>& wall,
                                    const std::vector<int>& hitFace)
{
  const Patches p = findPatches(mesh, wall);
  std::vector<int> side = sidesAcrossWall(p, oppositePatches(mesh, p, hitFace));
  joinBorderingSides(p, side);
  double area[2] = {0.0, 0.0};
  for (size_t a = 0; a < p.count(); ++a)
    if (side[a] >= 0) area[side[a]] += p.area[a];
  const int keep = area[1] > area[0] ? 1 : 0;
  std::vector<std::uint8_t> skin(mesh.faceCount(), 0);
  for (size_t f = 0; f < skin.size(); ++f) skin[f] = side[static_cast<size_t>(p.of[f])] == keep;
  return skin;
}

}  // namespace spira
