#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "builtin_plugins.h"
#include "envelope_shapes.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/planner.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {
namespace {

const DecomposerPlugin& envelope()
{
  return builtinRegistry().decomposer("decomposer.envelope_projection");
}

double lineLength(const Polyline& l)
{
  double s = 0;
  for (size_t i = 1; i < l.size(); ++i) s += (l[i] - l[i - 1]).norm();
  return s;
}

DecomposeInput openInput(const TriangleMesh& mesh, const MeshReport& r)
{
  return DecomposeInput{mesh, r.partClass, r.boundaryLoops[0], r.boundaryLoops[1], std::nullopt};
}

TEST(DecomposerEnvelope, IsRegisteredWithASoundSchema)
{
  const DecomposerPlugin& p = envelope();
  EXPECT_EQ(p.kind(), PluginKind::Decomposer);
  EXPECT_TRUE(p.schema().selfCheck().empty());
  const ParamDef* n = p.schema().find("points_per_rev");
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(std::get<std::int64_t>(n->defaultValue), 360);
  const ParamDef* axis = p.schema().find("axis");
  ASSERT_NE(axis, nullptr);
  EXPECT_EQ(axis->type, ParamType::Choice);
  EXPECT_EQ(std::get<std::string>(axis->defaultValue), "auto");
  ASSERT_NE(p.schema().find("level_spacing"), nullptr);
  EXPECT_EQ(p.schema().find("start_angle")->unit, "deg");
}

TEST(DecomposerEnvelope, AcceptsOpenPartsOnly)
{
  const TriangleMesh tube = makeOpenCylinder(10, 30, 48, 15);
  const MeshReport r = validateMesh(tube);
  std::string why;
  EXPECT_TRUE(envelope().accepts(openInput(tube, r), &why));

  const TriangleMesh dome = makeHemisphere(10, 48, 12);
  const MeshReport rd = validateMesh(dome);
  DecomposeInput closed{dome, rd.partClass, rd.boundaryLoops[0], std::nullopt, std::nullopt};
  EXPECT_FALSE(envelope().accepts(closed, &why));
  EXPECT_NE(why.find("open parts only"), std::string::npos) << why;
  NullProgress progress;
  EXPECT_THROW(envelope().decompose(closed, ParamSet{}, progress), InputError);
}

TEST(DecomposerEnvelope, AutoAxisDecomposesACylinderThroughItsSkeleton)
{
  const double R = 15, H = 50;
  const TriangleMesh tube = makeOpenCylinder(R, H, 96, 40);
  const MeshReport r = validateMesh(tube);
  ParamSet params;
  params.set("points_per_rev", std::int64_t{90});
  params.set("level_spacing", 2.5);
  NullProgress progress;
  const DecomposeResult res = envelope().decompose(openInput(tube, r), params, progress);
  ASSERT_EQ(res.generatrices.lines.size(), 90u);
  ASSERT_EQ(res.generatrices.normals.size(), 90u);
  EXPECT_FALSE(res.generatrices.hasClosurePoint);
  for (const Polyline& l : res.generatrices.lines) {
    ASSERT_EQ(l.size(), 21u);
    EXPECT_NEAR(lineLength(l), H, 2e-3 * H);
    EXPECT_LT(std::hypot(l.back().x() - l.front().x(), l.back().y() - l.front().y()), 1e-9);
  }
}

// Every run, in either axis mode, gives the cone's slant length, and the same generatrices to the
// bit: the skeleton the axis is fitted through is the same on every run.
TEST(DecomposerEnvelope, RepeatedRunsOnAConeGiveTheSlantLengthEveryTime)
{
  const double r0 = 35, r1 = 25, H = 60;
  const TriangleMesh cone = makeOpenCone(r0, r1, H, 96, 40);
  const MeshReport r = validateMesh(cone);
  const double slant = std::hypot(H, r0 - r1);
  for (const char* axis : {"auto", "skeleton"}) {
    Generatrices first;
    for (int run = 0; run < 3; ++run) {
      SCOPED_TRACE(std::string(axis) + " run " + std::to_string(run));
      ParamSet params;
      params.set("points_per_rev", std::int64_t{48});
      params.set("axis", std::string(axis));
      NullProgress progress;
      const DecomposeResult res = envelope().decompose(openInput(cone, r), params, progress);
      ASSERT_EQ(res.generatrices.lines.size(), 48u);
      for (const Polyline& l : res.generatrices.lines)
        EXPECT_NEAR(lineLength(l), slant, (axis[0] == 'a' ? 1e-9 : 5e-4) * slant);
      if (run == 0)
        first = res.generatrices;
      else
        EXPECT_TRUE(res.generatrices == first);
    }
  }
}

TEST(DecomposerEnvelope, SkeletonAxisFollowsAnInclinedPart)
{
  const double R = 12, H = 50, lean = degToRad(15);
  const TriangleMesh part = test::obliqueCylinder(R, H, lean, 96, 40);
  const MeshReport r = validateMesh(part);
  ParamSet params;
  params.set("points_per_rev", std::int64_t{48});
  params.set("axis", std::string("skeleton"));
  NullProgress progress;
  const DecomposeResult res = envelope().decompose(openInput(part, r), params, progress);
  ASSERT_EQ(res.generatrices.lines.size(), 48u);
  // Projected towards the skeleton, not the vertical: the lines follow the leaning wall, each
  // H / cos(lean) long. (Projected towards the vertical through the base centroid, the rays
  // would cross the wall at a drifting angle and the lines would bend round it.)
  const double expected = H / std::cos(lean);
  for (const Polyline& l : res.generatrices.lines) {
    EXPECT_NEAR(lineLength(l), expected, 2e-3 * expected);
    EXPECT_NEAR(l.back().x() - l.front().x(), H * std::tan(lean), 2e-3 * H);
  }
}

TEST(DecomposerEnvelope, RefusesAPartWhoseSkeletonDoesNotRise)
{
  const TriangleMesh arch = test::archTube(30, 6, 32, 60);
  const MeshReport r = validateMesh(arch);
  ASSERT_EQ(r.partClass, PartClass::Open) << r.toText();
  NullProgress progress;
  try {
    envelope().decompose(openInput(arch, r), ParamSet{}, progress);
    FAIL() << "an arch was decomposed by envelope projection";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not rise steadily"), std::string::npos) << e.what();
    EXPECT_NE(e.hint().find("--strategy isovalue"), std::string::npos) << e.hint();
  }
}

TEST(DecomposerEnvelope, HonoursCancellation)
{
  const TriangleMesh tube = makeOpenCylinder(10, 30, 48, 15);
  const MeshReport r = validateMesh(tube);
  CallbackProgress cancelled;
  cancelled.cancel();
  ParamSet params;
  params.set("axis", std::string("vertical"));
  EXPECT_THROW(envelope().decompose(openInput(tube, r), params, cancelled), Cancelled);
}

TEST(DecomposerEnvelope, PlansAFeasibleSpiralThroughThePlanner)
{
  const double R = 20, H = 30;
  const TriangleMesh tube = makeOpenCylinder(R, H, 96, 30);
  const MeshReport report = validateMesh(tube);
  PlanRequest request(tube, report);
  request.decomposerId = "decomposer.envelope_projection";
  ParamSet params;
  params.set("points_per_rev", std::int64_t{120});
  params.set("axis", std::string("vertical"));
  request.params["decomposer.envelope_projection"] = params;
  NullProgress progress;
  const PlanOutput plan = planPart(builtinRegistry(), request, progress);
  ASSERT_EQ(plan.generatrices.lines.size(), 120u);
  EXPECT_NEAR(plan.spiral.report.generatrixLengthMin, H, 1e-6);
  EXPECT_NEAR(plan.spiral.report.generatrixLengthMax, H, 1e-6);
  EXPECT_TRUE(plan.feasible());
  EXPECT_FALSE(plan.spiral.trajectory.empty());
}

}  // namespace
}  // namespace spira
