#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "builtin_plugins.h"
#include "decomposer_envelope/envelope_projection.h"
#include "envelope_shapes.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {
namespace {

double lineLength(const Polyline& l)
{
  double s = 0;
  for (size_t i = 1; i < l.size(); ++i) s += (l[i] - l[i - 1]).norm();
  return s;
}

EnvelopeDecomposition project(const TriangleMesh& mesh, const ProjectionAxis& axis, size_t n,
                              double spacing = 0)
{
  const MeshReport r = validateMesh(mesh);
  EXPECT_EQ(r.partClass, PartClass::Open);
  EnvelopeOptions options;
  options.generatrixCount = n;
  options.pointSpacing = spacing;
  NullProgress progress;
  return decomposeByEnvelopeProjection(mesh, r.boundaryLoops[0], r.boundaryLoops[1], axis, options, progress);
}

TEST(EnvelopeProjection, CylinderGeneratricesAreVerticalSegmentsOfTheHeight)
{
  const double R = 20, H = 60;
  const int segments = 96;
  const TriangleMesh tube = makeOpenCylinder(R, H, segments, 30);
  const EnvelopeDecomposition d = project(tube, ProjectionAxis::vertical(Vec3::Zero()), 120, 2.0);
  const Generatrices& g = d.generatrices;
  ASSERT_EQ(g.lines.size(), 120u);
  ASSERT_EQ(g.normals.size(), 120u);
  EXPECT_GT(d.envelopeRadius, R);
  for (size_t m = 0; m < g.lines.size(); ++m) {
    const Polyline& l = g.lines[m];
    ASSERT_EQ(l.size(), 31u);  // 60 mm at 2 mm: 30 segments
    ASSERT_EQ(g.normals[m].size(), l.size());
    EXPECT_NEAR(lineLength(l), H, 2e-3 * H);
    EXPECT_NEAR(l.front().z(), 0.0, 1e-9);
    EXPECT_NEAR(l.back().z(), H, 1e-9);
    const double theta = 2 * kPi * m / 120.0;
    for (size_t i = 0; i < l.size(); ++i) {
      const Vec3& p = l[i];
      EXPECT_NEAR(p.z(), H * i / 30.0, 1e-6);  // even spacing along the line
      // On the faceted wall, at the generatrix's angle.
      const double rho = std::hypot(p.x(), p.y());
      EXPECT_GE(rho, R * std::cos(kPi / segments) - 1e-9);
      EXPECT_LE(rho, R + 1e-9);
      EXPECT_NEAR(std::remainder(std::atan2(p.y(), p.x()) - theta, 2 * kPi), 0.0, 1e-9);
      const Vec3 radial = Vec3(p.x(), p.y(), 0).normalized();
      EXPECT_GT(g.normals[m][i].dot(radial), 0.99);
      EXPECT_NEAR(g.normals[m][i].norm(), 1.0, 1e-12);
    }
  }
}

TEST(EnvelopeProjection, TruncatedConeGeneratricesHaveTheSlantLength)
{
  const double r0 = 25, r1 = 15, H = 40;
  const TriangleMesh cone = makeOpenCone(r0, r1, H, 128, 40);
  const EnvelopeDecomposition d = project(cone, ProjectionAxis::vertical(Vec3::Zero()), 90);
  const double slant = std::hypot(H, r0 - r1);
  ASSERT_EQ(d.generatrices.lines.size(), 90u);
  for (const Polyline& l : d.generatrices.lines) {
    EXPECT_NEAR(lineLength(l), slant, 2e-3 * slant);
    EXPECT_NEAR(std::hypot(l.front().x(), l.front().y()), r0, 1e-3 * r0);
    EXPECT_NEAR(std::hypot(l.back().x(), l.back().y()), r1, 1e-3 * r1);
  }
}

TEST(EnvelopeProjection, EnvelopeGeneratricesFollowASlopedRim)
{
  const double R = 15, h0 = 40, slope = degToRad(25);
  const TriangleMesh part = test::slopedCylinder(R, h0, slope, 120, 40);
  const EnvelopeDecomposition d = project(part, ProjectionAxis::vertical(Vec3::Zero()), 72);
  ASSERT_EQ(d.generatrices.lines.size(), 72u);
  for (size_t m = 0; m < 72; ++m) {
    const double theta = 2 * kPi * m / 72.0;
    const double expected = h0 + R * std::cos(theta) * std::tan(slope);
    const Polyline& l = d.generatrices.lines[m];
    EXPECT_NEAR(lineLength(l), expected, 2e-3 * expected) << "angle " << radToDeg(theta);
    EXPECT_NEAR(l.back().z(), expected, 2e-3 * expected);
  }
}

TEST(EnvelopeProjection, ProjectsTowardsAnInclinedAxis)
{
  const double R = 12, H = 50, lean = degToRad(15);
  const TriangleMesh part = test::obliqueCylinder(R, H, lean, 96, 40);
  const ProjectionAxis axis = ProjectionAxis::line(Vec3::Zero(), Vec3(H * std::tan(lean), 0, H));
  const EnvelopeDecomposition d = project(part, axis, 60);
  const double expected = H / std::cos(lean);
  for (const Polyline& l : d.generatrices.lines) {
    EXPECT_NEAR(lineLength(l), expected, 2e-3 * expected);
    for (const Vec3& p : l) EXPECT_NEAR(std::hypot(p.x() - p.z() * std::tan(lean), p.y()), R, 2e-3 * R);
  }
}

TEST(EnvelopeProjection, AnOverhangFailsWithItsHeightAndAngleWhileIsoValuesSucceed)
{
  const TriangleMesh wall = test::bulgedWall(20, 96);
  const MeshReport report = validateMesh(wall);
  ASSERT_EQ(report.partClass, PartClass::Open) << report.toText();
  try {
    project(wall, ProjectionAxis::vertical(Vec3::Zero()), 60);
    FAIL() << "the overhang was projected";
  } catch (const InputError& e) {
    const std::string what = e.what();
    // The lowest place the envelope cannot see: the bead's bottom, z = 13, where the hits jump
    // from the neck (r = 20) out to the bead (r = 30).
    const size_t at = what.find("z = ");
    ASSERT_NE(at, std::string::npos) << what;
    EXPECT_NEAR(std::stod(what.substr(at + 4)), 13.0, 0.3) << what;
    EXPECT_NE(what.find("angle "), std::string::npos) << what;
    EXPECT_NE(what.find("overhang"), std::string::npos) << what;
    EXPECT_NE(what.find("60 of 60 generatrices"), std::string::npos) << what;
    EXPECT_NE(e.hint().find("--strategy isovalue"), std::string::npos) << e.hint();
    EXPECT_NE(e.hint().find("geodesic"), std::string::npos) << e.hint();
  }

  // The iso-value strategy works on the surface itself and decomposes the same part.
  const DecomposerPlugin& iso = builtinRegistry().decomposer("decomposer.isovalue");
  DecomposeInput in{wall, report.partClass, report.boundaryLoops[0], report.boundaryLoops[1], std::nullopt};
  ParamSet params;
  params.set("points_per_rev", std::int64_t{60});
  NullProgress progress;
  const DecomposeResult res = iso.decompose(in, params, progress);
  ASSERT_EQ(res.generatrices.lines.size(), 60u);
  // Its generatrices run over the bead: longer than the straight 50 mm neck.
  for (const Polyline& l : res.generatrices.lines) {
    EXPECT_NEAR(l.front().z(), 0.0, 1e-6);
    EXPECT_NEAR(l.back().z(), 50.0, 1e-6);
    EXPECT_GT(lineLength(l), 60.0);
  }
}

TEST(EnvelopeProjection, RefusesAnAxisOutsideThePart)
{
  const TriangleMesh tube = makeOpenCylinder(10, 30, 48, 10);
  try {
    project(tube, ProjectionAxis::vertical(Vec3(25, 0, 0)), 36);
    FAIL() << "an axis outside the part was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("0 times around"), std::string::npos) << e.what();
  }
}

TEST(EnvelopeProjection, ResampledLinesShareOnePointCountAndStartAtTheStartAngle)
{
  const TriangleMesh part = test::slopedCylinder(10, 20, degToRad(30), 64, 20);
  const MeshReport r = validateMesh(part);
  EnvelopeOptions options;
  options.generatrixCount = 24;
  options.pointSpacing = 1.5;
  options.startAngle = degToRad(90);
  NullProgress progress;
  const EnvelopeDecomposition d =
      decomposeByEnvelopeProjection(part, r.boundaryLoops[0], r.boundaryLoops[1],
                                    ProjectionAxis::vertical(Vec3::Zero()), options, progress);
  // Mean length 20 mm (the slope averages out) at 1.5 mm: 14 segments on every line.
  for (const Polyline& l : d.generatrices.lines) ASSERT_EQ(l.size(), 15u);
  const Vec3& first = d.generatrices.lines[0].front();
  EXPECT_NEAR(first.x(), 0.0, 1e-9);
  EXPECT_GT(first.y(), 9.9);
  // Counter-clockwise seen from above: line 1 is a quarter of a turn / 6 further.
  const Vec3& second = d.generatrices.lines[1].front();
  EXPECT_NEAR(std::atan2(second.y(), second.x()), degToRad(105), 1e-9);
  // Points spread evenly along each line.
  for (const Polyline& l : d.generatrices.lines) {
    const double step = lineLength(l) / 14.0;
    for (size_t i = 1; i < l.size(); ++i) EXPECT_NEAR((l[i] - l[i - 1]).norm(), step, 1e-6 * step);
  }
  EXPECT_GT(d.raysCast, 24u * 14u);
}

}  // namespace
}  // namespace spira
