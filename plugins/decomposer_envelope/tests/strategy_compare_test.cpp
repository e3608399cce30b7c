#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "builtin_plugins.h"
#include "envelope_shapes.h"
#include "spira/base/progress.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/strategy_compare.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/plugin/strategy_name.h"

namespace spira::test {
namespace {

const char* const kDecomposers[] = {"decomposer.isovalue", "decomposer.geodesic",
                                    "decomposer.envelope_projection"};

Comparison compare(const TriangleMesh& mesh, int pointsPerRev)
{
  const MeshReport report = validateMesh(mesh);
  PlanRequest request(mesh, report);
  for (const char* id : kDecomposers) request.params[id].set("points_per_rev", std::int64_t{pointsPerRev});
  NullProgress progress;
  return compareStrategies(builtinRegistry(), request, progress);
}

// The outcome of decomposer `id`; a comparison names each strategy by its one name.
const StrategyOutcome& outcome(const Comparison& c, const std::string& id)
{
  for (const StrategyOutcome& s : c.strategies)
    if (s.strategy == strategyName(id)) return s;
  throw std::runtime_error("no strategy " + id);
}

// Every strategy's generatrices are the analytic ones, so the spirals are the same: equal
// lengths (0.2 %) and equal revolution counts.
void expectSameSpirals(const Comparison& c, double length)
{
  int revolutions = -1;
  for (const char* id : kDecomposers) {
    SCOPED_TRACE(id);
    const StrategyOutcome& s = outcome(c, id);
    ASSERT_TRUE(s.ran) << s.failure;
    EXPECT_TRUE(s.feasible);
    EXPECT_EQ(s.outside, 0u);
    EXPECT_NEAR(s.generatrixLengthMin, length, 0.002 * length);
    EXPECT_NEAR(s.generatrixLengthMax, length, 0.002 * length);
    if (revolutions < 0) revolutions = s.revolutions;
    EXPECT_EQ(s.revolutions, revolutions);
  }
  EXPECT_GT(revolutions, 20);
}

TEST(StrategyCompare, OnACylinderAllThreeStrategiesGiveTheHeightAndOneRevolutionCount)
{
  const double H = 60.0;
  expectSameSpirals(compare(makeOpenCylinder(30.0, H, 96, 40), 96), H);
}

TEST(StrategyCompare, OnATruncatedConeAllThreeStrategiesGiveTheSlantLength)
{
  const double r0 = 35.0, r1 = 25.0, H = 60.0;
  expectSameSpirals(compare(makeOpenCone(r0, r1, H, 96, 40), 96), std::hypot(H, r0 - r1));
}

// The bulge hides part of the wall from the envelope: that strategy fails and says where, the
// two that work on the surface plan the part.
TEST(StrategyCompare, ABulgedWallDefeatsOnlyTheEnvelopeProjection)
{
  const TriangleMesh wall = bulgedWall(20, 96);
  const MeshReport report = validateMesh(wall);
  PlanRequest request(wall, report);
  for (const char* id : kDecomposers) request.params[id].set("points_per_rev", std::int64_t{60});
  // A part of revolution: the envelope projects towards its axis.
  request.params["decomposer.envelope_projection"].set("axis", std::string("vertical"));
  NullProgress progress;
  const Comparison c = compareStrategies(builtinRegistry(), request, progress);
  const StrategyOutcome& env = outcome(c, "decomposer.envelope_projection");
  EXPECT_FALSE(env.ran);
  EXPECT_NE(env.failure.find("overhang"), std::string::npos) << env.failure;
  const size_t at = env.failure.find("z = ");
  ASSERT_NE(at, std::string::npos) << env.failure;
  EXPECT_NEAR(std::stod(env.failure.substr(at + 4)), 13.0, 0.3) << env.failure;
  EXPECT_NE(env.failure.find("angle "), std::string::npos) << env.failure;
  for (const char* id : {"decomposer.isovalue", "decomposer.geodesic"}) {
    SCOPED_TRACE(id);
    const StrategyOutcome& s = outcome(c, id);
    ASSERT_TRUE(s.ran) << s.failure;
    EXPECT_GT(s.generatrixLengthMin, 60.0);  // over the bead: longer than the 50 mm neck
    EXPECT_GT(s.revolutions, 20);
  }
}

}  // namespace
}  // namespace spira::test
