// Times welding and validation of a ~1,000,000-triangle mesh built in code: an open cylinder
// (2000 segments x 250 rings, about 500k unique points), as an STL-ordered soup and shuffled.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <random>
#include <thread>
#include <vector>

#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/mesh/mesh_weld.h"

using namespace spira;

namespace {

double bestOf3(const std::function<void()>& run)
{
  double best = 1e300;
  for (int i = 0; i < 3; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    run();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

std::vector<Vec3> soupOf(const TriangleMesh& m, const std::vector<size_t>& order)
{
  std::vector<Vec3> corners;
  corners.reserve(3 * order.size());
  for (size_t f : order)
    for (int v : m.faces[f]) corners.push_back(m.vertices[v]);
  return corners;
}

bool benchSoup(const char* name, const std::vector<Vec3>& soup, size_t expectedVertices)
{
  TriangleMesh welded;
  const double weld = bestOf3([&] { welded = weldTriangleSoup(soup); });
  MeshReport report;
  const double validate = bestOf3([&] { report = validateMesh(welded); });
  std::printf(
      "%-10s %9zu triangles -> %8zu vertices   weld %7.1f ms   validate %7.1f ms   (%s, %zu loops, %s)\n",
      name, soup.size() / 3, welded.vertexCount(), 1e3 * weld, 1e3 * validate,
      partClassName(report.partClass), report.boundaryLoops.size(),
      report.issues.empty() ? "no issues" : "ISSUES");
  return welded.vertexCount() == expectedVertices && report.issues.empty();
}

}  // namespace

int main()
{
  const TriangleMesh cylinder = makeOpenCylinder(50.0, 100.0, 2000, 250);
  const TriangleMesh dome = makeHemisphere(50.0, 2000, 250);
  std::printf("bench_mesh: %u hardware threads, best of 3\n", std::thread::hardware_concurrency());

  std::vector<size_t> order(cylinder.faceCount());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  bool ok = benchSoup("cylinder", soupOf(cylinder, order), cylinder.vertexCount());
  std::vector<size_t> shuffled = order;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(1));
  ok &= benchSoup("shuffled", soupOf(cylinder, shuffled), cylinder.vertexCount());

  std::vector<size_t> domeOrder(dome.faceCount());
  for (size_t i = 0; i < domeOrder.size(); ++i) domeOrder[i] = i;
  ok &= benchSoup("dome", soupOf(dome, domeOrder), dome.vertexCount());
  if (!ok) std::printf("bench_mesh: UNEXPECTED RESULT (vertex count or issues)\n");
  return ok ? 0 : 1;
}
