#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "builtin_plugins.h"
#include "spira/base/error.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {
namespace {

std::vector<int> baseVertices(const TriangleMesh& mesh)
{
  const MeshReport report = validateMesh(mesh);
  EXPECT_EQ(report.boundaryLoops.size(), 1u);
  return report.boundaryLoops.at(0).vertices;
}

const ClosureFinderPlugin& finder()
{
  return builtinRegistry().closureFinder("closure.max_min_geodesic");
}

TEST(ClosureMaxMinGeodesic, HemispherePoleWithinHalfMillimetre)
{
  const double R = 60.0;
  const int segments = segmentsForEdge(R, R / 50.0);
  const TriangleMesh dome = makeHemisphere(R, segments, segments / 4);
  NullProgress progress;
  const ClosureResult r = finder().find({dome, baseVertices(dome)}, ParamSet(), progress);
  EXPECT_LT((r.point - Vec3(0, 0, R)).norm(), 0.5);
  // The largest smallest distance to the base circle is the quarter meridian, pi R / 2.
  EXPECT_NEAR(r.distance, kPi * R / 2.0, 0.01 * kPi * R / 2.0);
  ASSERT_GE(r.face, 0);
  EXPECT_NEAR(r.barycentric.sum(), 1.0, 1e-12);
}

// A dome whose top is a flat disc triangulated as a fan from one rim vertex: no vertex lies at
// the centre of the disc, where the true maximum is (by symmetry). The best vertex is on the rim,
// about 2.1 mm off; refinement must land inside a face, near the centre.
TriangleMesh domeWithFanCap(double R, double capAngle)
{
  std::vector<Eigen::Vector2d> profile;
  const int n = 40;
  for (int i = 0; i <= n; ++i) {
    const double a = (kPi / 2.0 - capAngle) * i / n;
    profile.emplace_back(R * std::cos(a), R * std::sin(a));
  }
  TriangleMesh mesh = makeRevolved(profile, 96);
  const double topZ = R * std::cos(capAngle);
  std::vector<int> rim;
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    if (std::abs(mesh.vertices[v].z() - topZ) < 1e-9) rim.push_back(static_cast<int>(v));
  std::sort(rim.begin(), rim.end(), [&](int a, int b) {
    return std::atan2(mesh.vertices[a].y(), mesh.vertices[a].x()) <
           std::atan2(mesh.vertices[b].y(), mesh.vertices[b].x());
  });
  for (size_t k = 1; k + 1 < rim.size(); ++k) mesh.faces.push_back({rim[0], rim[k], rim[k + 1]});
  return mesh;
}

TEST(ClosureMaxMinGeodesic, RefinementFindsAnOffVertexPeak)
{
  const double R = 60.0, capAngle = degToRad(2.0);
  const TriangleMesh dome = domeWithFanCap(R, capAngle);
  const Vec3 centre(0.0, 0.0, R * std::cos(capAngle));
  NullProgress progress;
  ParamSet vertexOnly;
  vertexOnly.set("refine", false);
  const ClosureResult coarse = finder().find({dome, baseVertices(dome)}, vertexOnly, progress);
  const ClosureResult fine = finder().find({dome, baseVertices(dome)}, ParamSet(), progress);
  EXPECT_GT((coarse.point - centre).norm(), 2.0);
  EXPECT_LT((fine.point - centre).norm(), 0.5);
  EXPECT_GE(fine.distance, coarse.distance);
  const Face& face = dome.faces.at(static_cast<size_t>(fine.face));
  const Vec3 rebuilt = fine.barycentric[0] * dome.vertices[face[0]] +
                       fine.barycentric[1] * dome.vertices[face[1]] +
                       fine.barycentric[2] * dome.vertices[face[2]];
  EXPECT_LT((rebuilt - fine.point).norm(), 1e-9);
  EXPECT_GT(fine.barycentric.minCoeff(), 0.0) << "the refined point should be strictly inside a face";
}

TEST(ClosureMaxMinGeodesic, EmptyBaseIsAnInputError)
{
  const TriangleMesh dome = makeHemisphere(10.0, 32, 8);
  NullProgress progress;
  EXPECT_THROW(finder().find({dome, {}}, ParamSet(), progress), InputError);
}

}  // namespace
}  // namespace spira
