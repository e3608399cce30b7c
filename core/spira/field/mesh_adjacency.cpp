#include "spira/field/mesh_adjacency.h"

#include <algorithm>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "spira/base/error.h"

namespace spira {
namespace {

bool usableFace(const Face& f)
{
  return f[0] != f[1] && f[1] != f[2] && f[0] != f[2];
}

void checkIndices(const TriangleMesh& mesh)
{
  const int n = int(mesh.vertices.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    for (int v : mesh.faces[f]) {
      if (v < 0 || v >= n)
        throw InputError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                             " but the mesh has " + std::to_string(n) + " vertices",
                         "re-import or repair the mesh");
    }
  }
}

// Neighbours of v with multiplicity (each incident face adds its two other vertices), sorted.
void gatherNeighbors(const TriangleMesh& mesh, const MeshAdjacency& a, int v, std::vector<int>& out)
{
  out.clear();
  for (int c = a.cornerStart[v]; c < a.cornerStart[v + 1]; ++c) {
    const Face& f = mesh.faces[a.corners[c] / 3];
    const int k = a.corners[c] % 3;
    out.push_back(f[(k + 1) % 3]);
    out.push_back(f[(k + 2) % 3]);
  }
  std::sort(out.begin(), out.end());
}

void labelComponents(MeshAdjacency& a)
{
  const int n = a.vertexCount();
  a.component.assign(n, -1);
  std::vector<int> stack;
  for (int seed = 0; seed < n; ++seed) {
    if (a.component[seed] >= 0) continue;
    const int label = a.componentCount++;
    a.component[seed] = label;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int k = a.neighborStart[v]; k < a.neighborStart[v + 1]; ++k) {
        const int w = a.neighbors[k];
        if (a.component[w] < 0) {
          a.component[w] = label;
          stack.push_back(w);
        }
      }
    }
  }
}

}  // namespace

MeshAdjacency buildMeshAdjacency(const TriangleMesh& mesh)
{
  checkIndices(mesh);
  const int n = int(mesh.vertices.size());
  MeshAdjacency a;
  a.cornerStart.assign(n + 1, 0);
  for (const Face& f : mesh.faces)
    if (usableFace(f))
      for (int v : f) ++a.cornerStart[v + 1];
  for (int v = 0; v < n; ++v) a.cornerStart[v + 1] += a.cornerStart[v];
  a.corners.resize(a.cornerStart[n]);
  {
    std::vector<int> next(a.cornerStart.begin(), a.cornerStart.end() - 1);
    for (size_t f = 0; f < mesh.faces.size(); ++f)
      if (usableFace(mesh.faces[f]))
        for (int k = 0; k < 3; ++k) a.corners[next[mesh.faces[f][k]]++] = int(3 * f + k);
  }

  // Two parallel passes: count distinct neighbours, then write them.
  a.onBoundary.assign(n, 0);
  a.neighborStart.assign(n + 1, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& r) {
    std::vector<int> buf;
    for (int v = r.begin(); v < r.end(); ++v) {
      gatherNeighbors(mesh, a, v, buf);
      int distinct = 0;
      for (size_t i = 0; i < buf.size();) {
        size_t j = i;
        while (j < buf.size() && buf[j] == buf[i]) ++j;
        if (j - i == 1) a.onBoundary[v] = 1;
        ++distinct;
        i = j;
      }
      a.neighborStart[v + 1] = distinct;
    }
  });
  for (int v = 0; v < n; ++v) a.neighborStart[v + 1] += a.neighborStart[v];
  a.neighbors.resize(a.neighborStart[n]);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& r) {
    std::vector<int> buf;
    for (int v = r.begin(); v < r.end(); ++v) {
      gatherNeighbors(mesh, a, v, buf);
      const auto end = std::unique(buf.begin(), buf.end());
      std::copy(buf.begin(), end, a.neighbors.begin() + a.neighborStart[v]);
    }
  });
  labelComponents(a);
  return a;
}

SymmetricSparseMatrix MeshAdjacency::lowerPattern() const
{
  const int n = vertexCount();
  SymmetricSparseMatrix m;
  m.size = n;
  m.columnStart.assign(n + 1, 0);
  for (int v = 0; v < n; ++v) {
    const auto begin = neighbors.begin() + neighborStart[v], end = neighbors.begin() + neighborStart[v + 1];
    m.columnStart[v + 1] = m.columnStart[v] + 1 + int(end - std::upper_bound(begin, end, v));
  }
  m.rowIndex.resize(m.columnStart[n]);
  m.values.assign(m.columnStart[n], 0.0);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 8192), [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v < r.end(); ++v) {
      const auto begin = neighbors.begin() + neighborStart[v], end = neighbors.begin() + neighborStart[v + 1];
      int k = m.columnStart[v];
      m.rowIndex[k++] = v;
      for (auto it = std::upper_bound(begin, end, v); it != end; ++it) m.rowIndex[k++] = *it;
    }
  });
  return m;
}

}  // namespace spira
