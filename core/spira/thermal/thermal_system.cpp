#include "spira/thermal/thermal_system.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"

namespace spira {
namespace {

// The capacity of a linear triangle: lumped (row sums, area / 3 on the diagonal) or consistent, exactly
// integrated (area / 12 * [2 1 1; 1 2 1; 1 1 2]; 000_dbb97c2716e10cc3.txt uses one Gauss point, which
// under-integrates this degree-2 integrand). The inactive filler is always lumped: consistent, it drove
// the unborn node ahead of the torch thousands of degrees below ambient under Crank-Nicolson.
double massFactor(int a, int b, bool lumped)
{
  if (lumped) return a == b ? 1.0 / 3.0 : 0.0;
  return a == b ? 2.0 / 12.0 : 1.0 / 12.0;
}

}  // namespace

ThermalSystem::ThermalSystem(const ThermalMesh& mesh, const ThermalMaterial& material,
                             const ThermalFilms& films, bool lumpedCapacity)
    : material_(material), films_(films), thickness_(mesh.thickness * 1e-3), lumped_(lumpedCapacity)
{
  const int n = int(mesh.nodeCount());
  // Pattern: every node with itself and its element neighbours.
  std::vector<std::vector<int>> adjacency(mesh.nodeCount());
  for (int v = 0; v < n; ++v) adjacency[size_t(v)].push_back(v);
  for (const auto& t : mesh.triangles)
    for (int a : t)
      for (int b : t)
        if (a != b) adjacency[size_t(a)].push_back(b);
  rowStart.assign(size_t(n) + 1, 0);
  for (int v = 0; v < n; ++v) {
    auto& row = adjacency[size_t(v)];
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    rowStart[size_t(v) + 1] = rowStart[size_t(v)] + int(row.size());
  }
  column.reserve(size_t(rowStart.back()));
  for (const auto& row : adjacency) column.insert(column.end(), row.begin(), row.end());
  const auto find = [&](int r, int c) {
    const auto b = column.begin() + rowStart[size_t(r)], e = column.begin() + rowStart[size_t(r) + 1];
    return int(std::lower_bound(b, e, c) - column.begin());
  };
  capacity.assign(column.size(), 0.0);
  conductance.assign(column.size(), 0.0);
  convectionLoad.assign(size_t(n), 0.0);
  capacitySum.assign(size_t(n), 0.0);
  lossWeight.assign(size_t(n), 0.0);

  elements_.resize(mesh.elementCount());
  active_.assign(mesh.elementCount(), 0);
  for (size_t i = 0; i < mesh.elementCount(); ++i) {
    Element& e = elements_[i];
    e.nodes = mesh.triangles[i];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        e.position[size_t(3 * a + b)] = find(e.nodes[size_t(a)], e.nodes[size_t(b)]);
    // The element's own frame (x along n1 n2, z its unit normal): the conduction is 2-D in it.
    const Vec3 p1 = mesh.nodes[size_t(e.nodes[0])] * 1e-3, p2 = mesh.nodes[size_t(e.nodes[1])] * 1e-3,
               p3 = mesh.nodes[size_t(e.nodes[2])] * 1e-3;
    const Vec3 x = (p2 - p1).normalized();
    const Vec3 z = x.cross(p3 - p1).normalized();
    const Vec3 y = z.cross(x);
    const double xs[3] = {0.0, (p2 - p1).dot(x), (p3 - p1).dot(x)};
    const double ys[3] = {0.0, 0.0, (p3 - p1).dot(y)};
    const double twiceArea = xs[1] * ys[2];
    if (!(std::abs(twiceArea) > 0.0))
      throw InternalError("thermal mesh element " + std::to_string(i) + " has no area");
    e.area = 0.5 * std::abs(twiceArea);
    double b[3], c[3];
    for (int a = 0; a < 3; ++a) {
      const int j = (a + 1) % 3, k = (a + 2) % 3;
      b[a] = (ys[j] - ys[k]) / twiceArea;
      c[a] = (xs[k] - xs[j]) / twiceArea;
    }
    for (int a = 0; a < 3; ++a)
      for (int d = 0; d < 3; ++d) e.gradient[size_t(3 * a + d)] = e.area * (b[a] * b[d] + c[a] * c[d]);
    const auto& edge = mesh.substrateEdge[i];
    if (edge[0] >= 0) {
      for (int a = 0; a < 3; ++a) {
        if (e.nodes[size_t(a)] == edge[0]) e.edgeA = a;
        if (e.nodes[size_t(a)] == edge[1]) e.edgeB = a;
      }
      e.edgeLength = (mesh.nodes[size_t(edge[1])] - mesh.nodes[size_t(edge[0])]).norm() * 1e-3;
    }
    add(e, material.inactiveVolumetricHeat(), true, material.inactiveConductivity, 0.0, 0.0);
  }
  // A node no element holds (never in a well-formed mesh) gets a token capacity so the system stays regular.
  for (int v = 0; v < n; ++v)
    if (rowStart[size_t(v) + 1] - rowStart[size_t(v)] == 1 && capacity[size_t(rowStart[size_t(v)])] == 0.0) {
      capacity[size_t(rowStart[size_t(v)])] = 1.0;
      capacitySum[size_t(v)] = 1.0;
    }
}

void ThermalSystem::add(const Element& e, double capacityScale, bool lumped, double conductivityScale,
                        double faceFilm, double edgeFilm)
{
  const double tau = thickness_;
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      const size_t p = size_t(e.position[size_t(3 * a + b)]);
      const double mass = e.area * massFactor(a, b, false);
      capacity[p] += capacityScale * tau * e.area * massFactor(a, b, lumped);
      conductance[p] += conductivityScale * tau * e.gradient[size_t(3 * a + b)] + 2.0 * faceFilm * mass;
    }
    const size_t v = size_t(e.nodes[size_t(a)]);
    capacitySum[v] += capacityScale * tau * e.area / 3.0;
    lossWeight[v] += 2.0 * faceFilm * e.area / 3.0;
    convectionLoad[v] += 2.0 * faceFilm * films_.airTemperature * e.area / 3.0;
  }
  if (e.edgeA >= 0 && edgeFilm != 0.0) {
    // The substrate contact: the edge times the thickness, consistent 1-D mass.
    const double w = edgeFilm * tau * e.edgeLength;
    const int ends[2] = {e.edgeA, e.edgeB};
    for (int a : ends) {
      for (int b : ends) conductance[size_t(e.position[size_t(3 * a + b)])] += w * (a == b ? 2.0 : 1.0) / 6.0;
      const size_t v = size_t(e.nodes[size_t(a)]);
      lossWeight[v] += w / 2.0;
      convectionLoad[v] += w / 2.0 * films_.airTemperature;
    }
  }
}

void ThermalSystem::activate(int element)
{
  if (active_[size_t(element)]) return;
  active_[size_t(element)] = 1;
  const Element& e = elements_[size_t(element)];
  add(e, -material_.inactiveVolumetricHeat(), true, -material_.inactiveConductivity, 0.0, 0.0);
  add(e, material_.volumetricHeat(), lumped_, material_.conductivity, films_.air, films_.substrate);
}

}  // namespace spira
