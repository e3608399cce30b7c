#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "builtin_plugins.h"
#include "contour_shapes.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {
namespace {

const DecomposerPlugin& isovalue()
{
  return builtinRegistry().decomposer("decomposer.isovalue");
}

TEST(DecomposerIsovalue, IsRegisteredWithASoundSchema)
{
  const DecomposerPlugin& p = isovalue();
  EXPECT_EQ(p.kind(), PluginKind::Decomposer);
  EXPECT_FALSE(p.label().empty());
  EXPECT_FALSE(p.description().empty());
  EXPECT_TRUE(p.schema().selfCheck().empty());
  const ParamDef* n = p.schema().find("points_per_rev");
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(std::get<std::int64_t>(n->defaultValue), 360);
  const ParamDef* s = p.schema().find("level_spacing");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->unit, "mm");
}

TEST(DecomposerIsovalue, AcceptsOpenAndClosedPartsWithAField)
{
  const TriangleMesh tube = makeOpenCylinder(10, 30, 48, 15);
  const MeshReport r = validateMesh(tube);
  const std::vector<double> field = test::heightField(tube, 1.0 / 30);
  DecomposeInput in{tube, r.partClass, r.boundaryLoops[0], r.boundaryLoops[1], std::nullopt};
  std::string why;
  // Without a field the plugin computes its own.
  EXPECT_TRUE(isovalue().accepts(in, &why));
  in.field = &field;
  EXPECT_TRUE(isovalue().accepts(in, &why));
  const std::vector<double> wrongSize(3, 0.0);
  in.field = &wrongSize;
  EXPECT_FALSE(isovalue().accepts(in, &why));
  EXPECT_NE(why.find("3 values"), std::string::npos) << why;
  NullProgress progress;
  EXPECT_THROW(isovalue().decompose(in, ParamSet{}, progress), InputError);
  in.field = &field;
  in.partClass = PartClass::Unsupported;
  EXPECT_FALSE(isovalue().accepts(in, &why));
  in.partClass = PartClass::Open;
  in.upper.reset();
  EXPECT_FALSE(isovalue().accepts(in, &why));

  const TriangleMesh dome = makeHemisphere(10, 48, 12);
  const MeshReport rd = validateMesh(dome);
  const std::vector<double> dist = test::hemisphereDistance(dome, 10);
  DecomposeInput closed{dome, rd.partClass, rd.boundaryLoops[0], std::nullopt, std::nullopt, &dist};
  EXPECT_TRUE(isovalue().accepts(closed, &why));
}

TEST(DecomposerIsovalue, DecomposesThroughTheRegistryWithParameters)
{
  const double H = 30;
  const TriangleMesh tube = makeOpenCylinder(10, H, 48, 15);
  const MeshReport r = validateMesh(tube);
  const std::vector<double> field = test::heightField(tube, 1.0 / H);
  DecomposeInput in{tube, r.partClass, r.boundaryLoops[0], r.boundaryLoops[1], std::nullopt, &field};
  ParamSet params;
  params.set("points_per_rev", std::int64_t{90});
  params.set("level_spacing", 3.0);
  NullProgress progress;
  const DecomposeResult res = isovalue().decompose(in, params, progress);
  ASSERT_EQ(res.generatrices.lines.size(), 90u);
  ASSERT_EQ(res.generatrices.normals.size(), 90u);
  for (const auto& l : res.generatrices.lines) {
    ASSERT_EQ(l.size(), 11u);  // base, 9 contours 3 mm apart, rim
    EXPECT_NEAR((l.back() - l.front()).norm(), H, 1e-9);
  }
  params.set("points_per_rev", std::int64_t{2});
  EXPECT_THROW(isovalue().decompose(in, params, progress), InputError);
}

double lineLength(const Polyline& l)
{
  double s = 0;
  for (size_t i = 1; i < l.size(); ++i) s += (l[i] - l[i - 1]).norm();
  return s;
}

TEST(DecomposerIsovalue, ComputesTheHarmonicFieldOfAnOpenPart)
{
  const double R = 15, H = 40;
  const TriangleMesh tube = makeOpenCylinder(R, H, 96, 40);
  const MeshReport r = validateMesh(tube);
  DecomposeInput in{tube, r.partClass, r.boundaryLoops[0], r.boundaryLoops[1], std::nullopt};
  ParamSet params;
  params.set("points_per_rev", std::int64_t{120});
  NullProgress progress;
  const DecomposeResult res = isovalue().decompose(in, params, progress);
  ASSERT_EQ(res.generatrices.lines.size(), 120u);
  EXPECT_FALSE(res.generatrices.hasClosurePoint);
  // The harmonic field of a cylinder is z / H: straight vertical generatrices.
  for (const auto& l : res.generatrices.lines) {
    EXPECT_NEAR(lineLength(l), H, 2e-3 * H);
    EXPECT_LT(std::hypot(l.back().x() - l.front().x(), l.back().y() - l.front().y()), 1e-6);
  }
}

TEST(DecomposerIsovalue, ComputesTheGeodesicDistanceOfAClosedPart)
{
  const double R = 25;
  const TriangleMesh dome = makeHemisphere(R, 128, 32);
  const MeshReport r = validateMesh(dome);
  DecomposeInput in{dome, r.partClass, r.boundaryLoops[0], std::nullopt, std::nullopt};
  ParamSet params;
  params.set("points_per_rev", std::int64_t{120});
  NullProgress progress;
  const DecomposeResult res = isovalue().decompose(in, params, progress);
  const Generatrices& g = res.generatrices;
  ASSERT_EQ(g.lines.size(), 120u);
  ASSERT_TRUE(g.hasClosurePoint);
  // The heat-method distance peaks at the pole (the hottest point closes the part).
  EXPECT_LT((g.closurePoint - Vec3(0, 0, R)).norm(), 1e-9);
  for (const auto& l : g.lines) {
    EXPECT_LT((l.back() - g.closurePoint).norm(), 1e-12);
    EXPECT_NEAR(lineLength(l), 0.5 * kPi * R, 5e-3 * 0.5 * kPi * R);
  }
}

TEST(DecomposerIsovalue, RefusesMultiBranchPartsWithTheSplitLevel)
{
  const TriangleMesh mesh = test::merged(makeOpenCylinder(5, 10, 40, 10),
                                         test::translated(makeOpenCylinder(5, 10, 40, 10), Vec3(20, 0, 5)));
  const MeshReport r = validateMesh(mesh);
  const std::vector<double> field = test::heightField(mesh);
  DecomposeInput in{mesh, PartClass::Closed, r.boundaryLoops[0], std::nullopt, std::nullopt, &field};
  NullProgress progress;
  try {
    isovalue().decompose(in, ParamSet{}, progress);
    FAIL() << "a two-branch part was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("splits into 2 branches"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spira
