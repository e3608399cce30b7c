// Closed parts: every generatrix is the exact geodesic from its base point to the closure point.
#include <gtest/gtest.h>

#include <cmath>

#include "builtin_plugins.h"
#include "decomposer_geodesic/geodesic_decomposition.h"
#include "geodesic_shapes.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/plugin/plugin_registry.h"

namespace spira::test {
namespace {

using geodesic::decomposeByGeodesics;
using geodesic::GeodesicDecomposition;
using geodesic::GeodesicOptions;

// The great-circle distance on the sphere of radius R about the origin.
double sphereDistance(const Vec3& p, const Vec3& q, double R)
{
  return R * std::acos(std::clamp(p.normalized().dot(q.normalized()), -1.0, 1.0));
}

TEST(GeodesicClosed, HemisphereGeneratricesAreMeridiansToTheClosurePoint)
{
  const double R = 40.0;
  const size_t n = 36;
  const Part part = makePart(makeHemisphere(R, 96, 24));
  ASSERT_EQ(part.report.partClass, PartClass::Closed);
  NullProgress progress;
  // The closure point from the closure plugin, as the planner passes it.
  const ClosureResult closure =
      builtinRegistry()
          .closureFinder("closure.max_min_geodesic")
          .find({part.mesh, part.report.boundaryLoops[0].vertices}, ParamSet(), progress);
  GeodesicOptions options;
  options.pointsPerRevolution = n;
  const GeodesicDecomposition d = decomposeByGeodesics(part.mesh, part.report.boundaryLoops[0], nullptr,
                                                       closure.point, nullptr, options, progress);
  const Generatrices& g = d.generatrices;
  ASSERT_EQ(g.lines.size(), n);
  ASSERT_TRUE(g.hasClosurePoint);
  EXPECT_LT((g.closurePoint - closure.point).norm(), 1e-6) << "the finder's point lies on the mesh";
  EXPECT_LT((g.closurePoint - Vec3(0, 0, R)).norm(), 0.5);
  for (size_t i = 0; i < n; ++i) {
    SCOPED_TRACE(i);
    const auto& line = g.lines[i];
    EXPECT_EQ(line.back(), g.closurePoint);
    EXPECT_NEAR(line.front().z(), 0.0, 1e-9);
    EXPECT_NEAR(angleOf(line.front()), 2.0 * kPi * double(i) / double(n), 1e-9);
    const double exact = sphereDistance(line.front(), g.closurePoint, R);
    EXPECT_NEAR(polylineLength(line), exact, 0.005 * exact);
    EXPECT_NEAR(d.exactLengths[i], exact, 0.005 * exact);
    // Converging: the last points of all generatrices close in on the closure point.
    EXPECT_LT((line[line.size() - 2] - g.closurePoint).norm(), 2.0 * R * kPi / 2.0 / double(line.size() - 1));
    for (size_t k = 0; k < line.size(); ++k) EXPECT_NEAR(line[k].norm(), R, 0.02 * R);
  }
}

TEST(GeodesicClosed, WithoutAClosurePointTheFarthestVertexFromTheBaseIsUsed)
{
  const double R = 30.0;
  const Part part = makePart(makeHemisphere(R, 64, 16));
  GeodesicOptions options;
  options.pointsPerRevolution = 16;
  NullProgress progress;
  const GeodesicDecomposition d = decomposeByGeodesics(part.mesh, part.report.boundaryLoops[0], nullptr,
                                                       std::nullopt, nullptr, options, progress);
  ASSERT_TRUE(d.generatrices.hasClosurePoint);
  EXPECT_LT((d.generatrices.closurePoint - Vec3(0, 0, R)).norm(), 1e-6) << "the pole is a vertex";
  for (const auto& line : d.generatrices.lines)
    EXPECT_NEAR(polylineLength(line), kPi * R / 2.0, 0.005 * kPi * R / 2.0);
}

TEST(GeodesicClosed, AClosurePointOnAnotherPieceIsAnInputError)
{
  TriangleMesh both = makeHemisphere(20.0, 32, 8);
  TriangleMesh other = makeHemisphere(20.0, 32, 8);
  const int offset = int(both.vertices.size());
  for (const Vec3& v : other.vertices) both.vertices.push_back(v + Vec3(100.0, 0.0, 0.0));
  for (const Face& f : other.faces) both.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  const Part part = makePart(both);
  ASSERT_EQ(part.report.boundaryLoops.size(), 2u);
  const BoundaryLoop& firstBase = part.report.boundaryLoops[0].vertices[0] < offset
                                      ? part.report.boundaryLoops[0]
                                      : part.report.boundaryLoops[1];
  GeodesicOptions options;
  options.pointsPerRevolution = 16;
  NullProgress progress;
  try {
    decomposeByGeodesics(part.mesh, firstBase, nullptr, Vec3(100.0, 0.0, 20.0), nullptr, options, progress);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no path on the surface"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("closure point"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spira::test
