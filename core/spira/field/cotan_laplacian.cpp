#include "spira/field/cotan_laplacian.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

namespace spira {

FaceCotangents faceCotangents(const Vec3& p0, const Vec3& p1, const Vec3& p2)
{
  const Vec3 p[3] = {p0, p1, p2};
  FaceCotangents out{{0.0, 0.0, 0.0}, 0.0};
  const double twiceArea = (p1 - p0).cross(p2 - p0).norm();
  out.area = 0.5 * twiceArea;
  const double scale = std::max({(p1 - p0).squaredNorm(), (p2 - p1).squaredNorm(), (p0 - p2).squaredNorm()});
  // Below this the angles are numerically meaningless; such a face must not poison the system.
  if (!(twiceArea > 1e-12 * scale)) return out;
  for (int k = 0; k < 3; ++k) {
    const Vec3 u = p[(k + 1) % 3] - p[k];
    const Vec3 w = p[(k + 2) % 3] - p[k];
    out.cot[k] = u.dot(w) / twiceArea;
  }
  return out;
}

CotanLaplacian buildCotanLaplacian(const TriangleMesh& mesh, const MeshAdjacency& adjacency)
{
  const int n = adjacency.vertexCount();
  const int faceCount = int(mesh.faces.size());
  std::vector<FaceCotangents> faces(faceCount);
  tbb::parallel_for(tbb::blocked_range<int>(0, faceCount, 8192), [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f) {
      const Face& t = mesh.faces[f];
      faces[f] = faceCotangents(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    }
  });

  CotanLaplacian op;
  op.stiffness = adjacency.lowerPattern();
  op.vertexArea.assign(n, 0.0);
  SymmetricSparseMatrix& k = op.stiffness;
  // Each column is written by one task only, so the gather needs no locks.
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& r) {
    for (int j = r.begin(); j < r.end(); ++j) {
      double diagonal = 0.0, area = 0.0;
      for (int c = adjacency.cornerStart[j]; c < adjacency.cornerStart[j + 1]; ++c) {
        const int f = adjacency.corners[c] / 3, corner = adjacency.corners[c] % 3;
        const FaceCotangents& fc = faces[f];
        area += fc.area / 3.0;
        const int a = mesh.faces[f][(corner + 1) % 3], b = mesh.faces[f][(corner + 2) % 3];
        const double wa = 0.5 * fc.cot[(corner + 2) % 3];  // edge j-a is opposite that corner
        const double wb = 0.5 * fc.cot[(corner + 1) % 3];
        diagonal += wa + wb;
        if (a > j) k.values[k.find(a, j)] -= wa;
        if (b > j) k.values[k.find(b, j)] -= wb;
      }
      k.values[k.columnStart[j]] = diagonal;
      op.vertexArea[j] = area;
    }
  });

  const auto& nb = adjacency.neighbors;
  const auto& ns = adjacency.neighborStart;
  // Deterministic reduce: the same chunks summed in the same order whatever the thread count (a
  // floating-point sum depends on its order, and the mean edge length sets the heat time step).
  const std::pair<double, long> sum = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<int>(0, n, 8192), std::pair<double, long>(0.0, 0),
      [&](const tbb::blocked_range<int>& r, std::pair<double, long> acc) {
        for (int v = r.begin(); v < r.end(); ++v)
          for (int e = ns[v]; e < ns[v + 1]; ++e)
            if (nb[e] > v) {
              acc.first += (mesh.vertices[nb[e]] - mesh.vertices[v]).norm();
              ++acc.second;
            }
        return acc;
      },
      [](std::pair<double, long> x, std::pair<double, long> y) {
        return std::pair<double, long>(x.first + y.first, x.second + y.second);
      });
  op.meanEdgeLength = sum.second > 0 ? sum.first / double(sum.second) : 0.0;
  return op;
}

}  // namespace spira
