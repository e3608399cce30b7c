// decomposer.geodesic through the registry and the planner, as the CLI and the GUI use it.
#include <gtest/gtest.h>

#include <cmath>

#include "builtin_plugins.h"
#include "geodesic_shapes.h"
#include "spira/base/error.h"
#include "spira/io/import_service.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/planning/planner.h"
#include "spira/plugin/plugin_registry.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

const DecomposerPlugin& geodesicPlugin()
{
  return builtinRegistry().decomposer("decomposer.geodesic");
}

TEST(GeodesicPlugin, SharesThePointsPerRevolutionKeyWithTheIsovalueDecomposer)
{
  const DecomposerPlugin& p = geodesicPlugin();
  EXPECT_EQ(p.kind(), PluginKind::Decomposer);
  EXPECT_TRUE(p.schema().selfCheck().empty());
  const ParamDef* mine = p.schema().find("points_per_rev");
  const ParamDef* theirs =
      builtinRegistry().decomposer("decomposer.isovalue").schema().find("points_per_rev");
  ASSERT_NE(mine, nullptr);
  ASSERT_NE(theirs, nullptr);
  EXPECT_EQ(mine->type, theirs->type);
  EXPECT_EQ(mine->defaultValue, theirs->defaultValue);
  EXPECT_EQ(mine->min, theirs->min);
  EXPECT_EQ(mine->max, theirs->max);
  ASSERT_NE(p.schema().find("level_spacing"), nullptr);
  EXPECT_EQ(p.schema().find("level_spacing")->unit, "mm");
  ASSERT_NE(p.schema().find("coverage_tolerance"), nullptr);
  ASSERT_NE(p.schema().find("fill_rounds"), nullptr);
}

TEST(GeodesicPlugin, AcceptsOpenAndClosedPartsOnly)
{
  const Part tube = makePart(makeOpenCylinder(10, 30, 48, 15));
  DecomposeInput in = tube.input();
  std::string why;
  EXPECT_TRUE(geodesicPlugin().accepts(in, &why));
  in.upper.reset();
  EXPECT_FALSE(geodesicPlugin().accepts(in, &why));
  EXPECT_NE(why.find("upper edge"), std::string::npos) << why;
  in.partClass = PartClass::Unsupported;
  EXPECT_FALSE(geodesicPlugin().accepts(in, &why));
  const Part dome = makePart(makeHemisphere(10, 48, 12));
  EXPECT_TRUE(geodesicPlugin().accepts(dome.input(), &why));
}

TEST(GeodesicPlugin, DecomposesWithItsParameters)
{
  const double H = 30;
  const Part tube = makePart(makeOpenCylinder(10, H, 64, 15));
  ParamSet params;
  params.set("points_per_rev", std::int64_t{40});
  params.set("level_spacing", 3.0);
  NullProgress progress;
  const DecomposeResult r = geodesicPlugin().decompose(tube.input(), params, progress);
  ASSERT_EQ(r.generatrices.lines.size(), 40u);
  for (const auto& line : r.generatrices.lines) {
    EXPECT_EQ(line.size(), 11u) << "30 mm at 3 mm spacing";
    EXPECT_NEAR(polylineLength(line), H, 0.002 * H);
  }
  params.set("points_per_rev", std::int64_t{3});
  EXPECT_THROW(geodesicPlugin().decompose(tube.input(), params, progress), InputError);
}

// Two separate tubes, the lower edge on one and the upper edge on the other: no generatrix exists.
TEST(GeodesicPlugin, AnUpperEdgeThatCannotBeReachedIsAnInputError)
{
  TriangleMesh mesh = makeOpenCylinder(20, 20, 32, 5);
  const TriangleMesh upper = makeOpenCylinder(20, 20, 32, 5);
  const int offset = int(mesh.vertices.size());
  for (const Vec3& v : upper.vertices) mesh.vertices.push_back(v + Vec3(0, 0, 30));
  for (const Face& f : upper.faces) mesh.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  const Part part = makePart(mesh);
  ASSERT_EQ(part.report.boundaryLoops.size(), 4u);
  DecomposeInput in{part.mesh, PartClass::Open, part.report.boundaryLoops.front(),
                    part.report.boundaryLoops.back(), std::nullopt};
  ASSERT_LT(in.lower.vertices[0], offset);
  ASSERT_GE(in.upper->vertices[0], offset);
  NullProgress progress;
  try {
    geodesicPlugin().decompose(in, ParamSet(), progress);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no path on the surface joins the base point"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("upper edge"), std::string::npos) << e.what();
    EXPECT_FALSE(e.hint().empty());
  }
}

TEST(GeodesicPlugin, StopsWhenCancelled)
{
  const Part tube = makePart(makeOpenCylinder(10, 30, 48, 15));
  CallbackProgress progress;
  progress.cancel();
  EXPECT_THROW(geodesicPlugin().decompose(tube.input(), ParamSet(), progress), Cancelled);
}

// End to end on the bundled sample: the planner with decomposer.geodesic gives the same spiral
// (revolution count) as with the iso-value decomposer: on a cylinder both generatrix sets are the
// straight vertical lines of length H.
TEST(GeodesicPlugin, PlansTheSampleCylinderLikeTheIsovalueDecomposer)
{
  NullProgress progress;
  const ImportedPart part = importPart(
      builtinRegistry(), sourceDir() / "resources" / "samples" / "open_cylinder.stl", nullptr, progress);
  PlanRequest request{part.mesh, part.report};
  request.decomposerId = "decomposer.geodesic";
  const PlanOutput geodesic = planPart(builtinRegistry(), request, progress);
  request.decomposerId = "decomposer.isovalue";
  const PlanOutput isovalue = planPart(builtinRegistry(), request, progress);

  RecordProperty("revolutions", geodesic.spiral.report.nRevolutions);
  for (const auto& [stage, seconds] : geodesic.timings)
    if (stage == "decomposition") RecordProperty("decomposition_seconds", std::to_string(seconds));
  EXPECT_EQ(geodesic.generatrices.lines.size(), 360u);
  EXPECT_GT(geodesic.spiral.report.nRevolutions, 10);
  EXPECT_EQ(geodesic.spiral.report.nRevolutions, isovalue.spiral.report.nRevolutions);
  EXPECT_EQ(geodesic.spiral.report.nLayers, isovalue.spiral.report.nLayers);
  EXPECT_NEAR(geodesic.spiral.report.generatrixLengthMin, isovalue.spiral.report.generatrixLengthMin, 0.01);
  EXPECT_NEAR(geodesic.spiral.report.generatrixLengthMax, isovalue.spiral.report.generatrixLengthMax, 0.01);
  EXPECT_TRUE(geodesic.feasible());
}

}  // namespace
}  // namespace spira::test
