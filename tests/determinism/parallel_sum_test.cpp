// Sums over a mesh come out the same to the bit whatever the thread count: they feed the plan
// (the mean edge length sets the heat method's time step and the default point spacing) and the
// report (the part's area). The bundled samples are too small to be split into several chunks, so
// the mesh here is large.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include <tbb/task_arena.h>

#include "spira/field/cotan_laplacian.h"
#include "spira/field/mesh_adjacency.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"

namespace spira {
namespace {

struct Sums {
  double area = 0, meanEdge = 0, reportArea = 0, reportMeanEdge = 0, laplacianMeanEdge = 0;
};

// A cone of 430k faces with its vertices moved by a smooth ripple, so that no two faces are alike.
TriangleMesh rippledCone()
{
  TriangleMesh mesh = makeOpenCone(40.0, 20.0, 60.0, 720, 300);
  for (Vec3& v : mesh.vertices) v += 0.3 * std::sin(0.7 * v.z() + 0.01 * v.x()) * Vec3(1.0, 0.5, 0.2);
  return mesh;
}

Sums sumsWith(int threads, const TriangleMesh& mesh)
{
  Sums s;
  tbb::task_arena arena(threads);
  arena.execute([&] {
    s.area = mesh.area();
    s.meanEdge = mesh.meanEdgeLength();
    const MeshReport report = validateMesh(mesh);
    s.reportArea = report.area;
    s.reportMeanEdge = report.meanEdgeLength;
    s.laplacianMeanEdge = buildCotanLaplacian(mesh, buildMeshAdjacency(mesh)).meanEdgeLength;
  });
  return s;
}

bool sameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(ParallelSums, AreTheSameWithAnyThreadCount)
{
  const TriangleMesh mesh = rippledCone();
  const Sums one = sumsWith(1, mesh);
  for (int threads : {2, 3, 4, 1}) {
    const Sums s = sumsWith(threads, mesh);
    EXPECT_TRUE(sameBits(s.area, one.area)) << threads << " threads: " << s.area - one.area;
    EXPECT_TRUE(sameBits(s.meanEdge, one.meanEdge)) << threads << " threads: " << s.meanEdge - one.meanEdge;
    EXPECT_TRUE(sameBits(s.reportArea, one.reportArea))
        << threads << " threads: " << s.reportArea - one.reportArea;
    EXPECT_TRUE(sameBits(s.reportMeanEdge, one.reportMeanEdge))
        << threads << " threads: " << s.reportMeanEdge - one.reportMeanEdge;
    EXPECT_TRUE(sameBits(s.laplacianMeanEdge, one.laplacianMeanEdge))
        << threads << " threads: " << s.laplacianMeanEdge - one.laplacianMeanEdge;
  }
}

}  // namespace
}  // namespace spira
