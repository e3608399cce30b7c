#include "spira/mesh/edge_table.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "spira/mesh/vertex_corners.h"
#include "spira/mesh/vertex_sort.h"

namespace spira {

namespace {

constexpr std::uint64_t kLow32 = 0xffffffffu;
constexpr size_t kVertexGrain = 4096;

}  // namespace

EdgeTable buildEdgeTable(const TriangleMesh& mesh, const std::vector<std::uint8_t>* useFace)
{
  const size_t nv = mesh.vertexCount();
  // Half-edges on their lower vertex, keyed (higher vertex << 32 | half-edge): sorting puts an
  // edge's half-edges together, in face order.
  const VertexSorted<std::uint64_t> sorted =
      sortByVertex<std::uint64_t>(mesh.faceCount(), nv, [&](size_t f, const auto& sink) {
        const Face& t = mesh.faces[f];
        if ((useFace != nullptr && (*useFace)[f] == 0) || hasRepeatedIndex(t)) return;
        for (int k = 0; k < 3; ++k) {
          const int a = t[k], b = t[(k + 1) % 3];
          sink(std::min(a, b), (static_cast<std::uint64_t>(std::max(a, b)) << 32) | (3 * f + k));
        }
      });
  const auto& keys = sorted.items;
  const auto& offset = sorted.offset;
  const auto startsEdge = [&](int i, int first) {
    return i == first || (keys[i] >> 32) != (keys[i - 1] >> 32);
  };

  std::vector<int> edgeBase(nv + 1, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, kVertexGrain),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t v = r.begin(); v != r.end(); ++v) {
                        int edges = 0;
                        for (int i = offset[v]; i < offset[v + 1]; ++i) edges += startsEdge(i, offset[v]);
                        edgeBase[v + 1] = edges;
                      }
                    });
  for (size_t v = 0; v < nv; ++v) edgeBase[v + 1] += edgeBase[v];

  EdgeTable t;
  const size_t ne = static_cast<size_t>(edgeBase[nv]);
  t.halfEdges.resize(keys.size());
  t.edgeStart.resize(ne + 1);
  t.edgeStart[ne] = static_cast<int>(keys.size());
  t.edgeOfHalfEdge.assign(3 * mesh.faceCount(), -1);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, kVertexGrain),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t v = r.begin(); v != r.end(); ++v) {
                        int e = edgeBase[v] - 1;
                        for (int i = offset[v]; i < offset[v + 1]; ++i) {
                          const int h = static_cast<int>(keys[i] & kLow32);
                          if (startsEdge(i, offset[v])) t.edgeStart[++e] = i;
                          t.halfEdges[i] = h;
                          t.edgeOfHalfEdge[h] = e;
                        }
                      }
                    });
  return t;
}

}  // namespace spira
