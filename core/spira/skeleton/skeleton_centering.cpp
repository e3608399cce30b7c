#include "spira/skeleton/skeleton_centering.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>
#include <utility>

#include "spira/base/units.h"

namespace spira {

namespace {

uint64_t edgeKey(int u, int v)
{
  if (u > v) std::swap(u, v);
  return (static_cast<uint64_t>(static_cast<uint32_t>(u)) << 32) | static_cast<uint32_t>(v);
}

// Where the plane crosses edge (u, v), computed from the lower vertex id so that both faces of
// the edge get the very same point.
Vec3 crossing(const TriangleMesh& mesh, const std::vector<double>& s, int u, int v)
{
  if (u > v) std::swap(u, v);
  const double t = s[u] / (s[u] - s[v]);
  return mesh.vertices[u] + t * (mesh.vertices[v] - mesh.vertices[u]);
}

struct Segment {
  uint64_t from = 0, to = 0;  // the crossed edges the segment starts and ends on
  Vec3 a, b;
};

struct Loop {
  Vec3 centroid = Vec3::Zero();
  double winding = 0.0;       // rad, signed about the plane normal
  double meanDistance = 0.0;  // of the loop's points from the node
};

std::vector<Segment> sectionSegments(const TriangleMesh& mesh, const Vec3& p, const Vec3& d,
                                     std::vector<double>& s)
{
  for (size_t v = 0; v < mesh.vertexCount(); ++v) s[v] = d.dot(mesh.vertices[v] - p);
  std::vector<Segment> out;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const Face& fc = mesh.faces[f];
    const bool up[3] = {s[fc[0]] >= 0, s[fc[1]] >= 0, s[fc[2]] >= 0};
    if (up[0] == up[1] && up[1] == up[2]) continue;
    // Going round the face (counter-clockwise from outside), the section enters it where the
    // boundary steps from the positive side to the negative one and leaves where it steps back,
    // so on an oriented surface the segments chain head to tail, with the direction d x N. Read
    // from the sides alone, the rule holds even where the plane passes through a vertex (zero
    // length segments), where a test on the segment's direction would be a coin toss.
    Segment seg;
    for (int k = 0; k < 3; ++k) {
      const int u = fc[k], v = fc[(k + 1) % 3];
      if (up[k] && !up[(k + 1) % 3]) {
        seg.from = edgeKey(u, v);
        seg.a = crossing(mesh, s, u, v);
      } else if (!up[k] && up[(k + 1) % 3]) {
        seg.to = edgeKey(u, v);
        seg.b = crossing(mesh, s, u, v);
      }
    }
    out.push_back(seg);
  }
  return out;
}

std::vector<Loop> closedLoops(const std::vector<Segment>& segments, const Vec3& p, const Vec3& d)
{
  std::unordered_map<uint64_t, size_t> startingAt;
  startingAt.reserve(segments.size() * 2);
  for (size_t i = 0; i < segments.size(); ++i) startingAt.emplace(segments[i].from, i);
  std::vector<char> used(segments.size(), 0);
  std::vector<Loop> loops;
  for (size_t first = 0; first < segments.size(); ++first) {
    if (used[first]) continue;
    Loop loop;
    double length = 0.0, distance = 0.0;
    size_t count = 0, i = first;
    bool closed = false;
    while (!used[i]) {
      used[i] = 1;
      const Segment& sg = segments[i];
      const Vec3 ra = sg.a - p, rb = sg.b - p;
      loop.winding += std::atan2(ra.cross(rb).dot(d), ra.dot(rb));
      const double l = (sg.b - sg.a).norm();
      loop.centroid += l * 0.5 * (sg.a + sg.b);
      length += l;
      distance += ra.norm();
      ++count;
      const auto next = startingAt.find(sg.to);
      if (next == startingAt.end()) break;
      if (next->second == first) {
        closed = true;
        break;
      }
      i = next->second;
    }
    if (!closed || !(length > 0)) continue;
    loop.centroid /= length;
    loop.meanDistance = distance / static_cast<double>(count);
    loops.push_back(loop);
  }
  return loops;
}

std::optional<Vec3> sectionCentroid(const TriangleMesh& mesh, const Vec3& p, const Vec3& d,
                                    std::vector<double>& s)
{
  const std::vector<Loop> loops = closedLoops(sectionSegments(mesh, p, d, s), p, d);
  const Loop* best = nullptr;
  for (const Loop& l : loops)
    if (std::abs(l.winding) > kPi && (!best || l.meanDistance < best->meanDistance)) best = &l;
  if (!best) return std::nullopt;
  return best->centroid;
}

}  // namespace

size_t centreInCrossSections(SkeletonGraph& graph, const TriangleMesh& mesh, Progress& progress)
{
  std::vector<std::vector<int>> neighbours(graph.nodes.size());
  for (const auto& e : graph.edges) {
    neighbours[e[0]].push_back(e[1]);
    neighbours[e[1]].push_back(e[0]);
  }
  std::vector<double> s(mesh.vertexCount());
  // Directions from the original positions, so the result does not depend on node order.
  const std::vector<Vec3> original = graph.nodes;
  size_t moved = 0;
  for (size_t n = 0; n < graph.nodes.size(); ++n) {
    progress.checkCancel();
    const auto& nb = neighbours[n];
    Vec3 d;
    if (nb.size() == 1)
      d = original[n] - original[nb[0]];
    else if (nb.size() == 2)
      d = original[nb[1]] - original[nb[0]];
    else
      continue;
    std::optional<Vec3> c;
    if (d.norm() > 0) c = sectionCentroid(mesh, original[n], d.normalized(), s);
    // Near a sloping free edge the skeleton bends towards it and its normal plane runs out
    // through the edge; the horizontal section, which Spira's upright parts always have, stays
    // closed there.
    if (!c) c = sectionCentroid(mesh, original[n], Vec3::UnitZ(), s);
    if (c) {
      graph.nodes[n] = *c;
      ++moved;
    }
  }
  return moved;
}

}  // namespace spira
