#include "spira/mesh/vertex_fans.h"

#include <algorithm>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace spira {

namespace {

struct Scratch {
  std::vector<int> corners;                 // the vertex's corners in counted faces
  std::vector<std::pair<int, int>> others;  // (other vertex of the face, local corner index)
  std::vector<int> parent;
};

int findRoot(std::vector<int>& parent, int x)
{
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

VertexFans computeVertexFans(const TriangleMesh& mesh, const std::vector<std::uint8_t>* useFace)
{
  return computeVertexFans(mesh, buildVertexCorners(mesh, useFace), nullptr);
}

VertexFans computeVertexFans(const TriangleMesh& mesh, const VertexCorners& vc,
                             const std::vector<std::uint8_t>* useFace)
{
  const size_t nv = mesh.vertexCount();
  VertexFans fans;
  fans.fanOfCorner.assign(3 * mesh.faceCount(), -1);
  fans.fanCount.assign(nv, 0);

  // Per vertex: faces sharing another vertex share the edge to it, so they are in one fan.
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, 2048), [&](const tbb::blocked_range<size_t>& r) {
    Scratch& s = scratch.local();
    for (size_t v = r.begin(); v != r.end(); ++v) {
      s.corners.clear();
      for (int i = vc.offset[v]; i < vc.offset[v + 1]; ++i)
        if (!useFace || (*useFace)[vc.corners[i] / 3]) s.corners.push_back(vc.corners[i]);
      const int d = static_cast<int>(s.corners.size());
      if (d == 0) continue;
      s.parent.resize(static_cast<size_t>(d));
      for (int i = 0; i < d; ++i) s.parent[i] = i;
      int count = d;
      const auto join = [&](int i, int j) {
        int a = findRoot(s.parent, i), b = findRoot(s.parent, j);
        if (a == b) return;
        if (a > b) std::swap(a, b);
        s.parent[b] = a;  // the smaller local index, so the smaller corner id, stays the root
        --count;
      };
      s.others.clear();
      for (int i = 0; i < d; ++i) {
        const int c = s.corners[i];
        const Face& f = mesh.faces[c / 3];
        s.others.emplace_back(f[(c % 3 + 1) % 3], i);
        s.others.emplace_back(f[(c % 3 + 2) % 3], i);
      }
      if (d <= 16) {
        // A handful of faces (the usual case): compare every pair, no sorting.
        for (int i = 1; i < d; ++i)
          for (int j = 0; j < i; ++j) {
            const int a0 = s.others[2 * i].first, a1 = s.others[2 * i + 1].first;
            const int b0 = s.others[2 * j].first, b1 = s.others[2 * j + 1].first;
            if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) join(i, j);
          }
      } else {
        std::sort(s.others.begin(), s.others.end());
        for (size_t j = 1; j < s.others.size(); ++j)
          if (s.others[j].first == s.others[j - 1].first) join(s.others[j].second, s.others[j - 1].second);
      }
      fans.fanCount[v] = count;
      for (int i = 0; i < d; ++i) fans.fanOfCorner[s.corners[i]] = s.corners[findRoot(s.parent, i)];
    }
  });
  return fans;
}

}  // namespace spira
