#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "contour_shapes.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/contour/isovalue_decomposition.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"

namespace spira {
namespace {

double lineLength(const Polyline& l)
{
  double s = 0;
  for (size_t i = 1; i < l.size(); ++i) s += (l[i] - l[i - 1]).norm();
  return s;
}

// Generatrix m uses a different point of every contour than any other generatrix.
void expectNoSharedPoints(const Generatrices& g, double minGap)
{
  const size_t n = g.lines.size(), C = g.lines[0].size() - (g.hasClosurePoint ? 1 : 0);
  for (size_t c = 0; c < C; ++c)
    for (size_t a = 0; a < n; ++a)
      for (size_t b = a + 1; b < n; ++b)
        ASSERT_GT((g.lines[a][c] - g.lines[b][c]).norm(), minGap)
            << "contour " << c << " lines " << a << ", " << b;
}

void expectShapesMatch(const Generatrices& g)
{
  ASSERT_EQ(g.normals.size(), g.lines.size());
  for (size_t m = 0; m < g.lines.size(); ++m) {
    ASSERT_EQ(g.normals[m].size(), g.lines[m].size());
    for (const auto& n : g.normals[m]) EXPECT_NEAR(n.norm(), 1.0, 1e-12);
  }
}

struct OpenCase {
  TriangleMesh mesh;
  MeshReport report;
};

OpenCase openPart(TriangleMesh mesh)
{
  OpenCase c{std::move(mesh), {}};
  c.report = validateMesh(c.mesh);
  return c;
}

TEST(IsovalueDecomposition, CylinderGivesStraightVerticalGeneratrices)
{
  const double R = 20, H = 50;
  const OpenCase part = openPart(makeOpenCylinder(R, H, 128, 50));
  ASSERT_EQ(part.report.partClass, PartClass::Open);
  // The harmonic field of a cylinder with 0 at the base and 1 at the rim is z / H.
  const std::vector<double> field = test::heightField(part.mesh, 1.0 / H);
  IsoDecompositionOptions opt;
  opt.pointsPerContour = 360;
  opt.levelSpacing = 2.0;
  NullProgress progress;
  const IsoDecomposition d = decomposeByIsoValues(part.mesh, field, part.report.boundaryLoops[0],
                                                  &part.report.boundaryLoops[1], std::nullopt, opt, progress);
  const Generatrices& g = d.generatrices;
  ASSERT_EQ(g.lines.size(), 360u);
  EXPECT_FALSE(g.hasClosurePoint);
  EXPECT_TRUE(d.warnings.empty());
  // Levels every 2 mm: base, 24 interior contours, rim.
  EXPECT_EQ(d.contours.size(), 26u);
  expectShapesMatch(g);
  for (const auto& l : g.lines) {
    ASSERT_EQ(l.size(), 26u);
    EXPECT_NEAR(l.front().z(), 0.0, 1e-12);
    EXPECT_NEAR(l.back().z(), H, 1e-12);
    for (size_t c = 1; c < l.size(); ++c) {
      EXPECT_LT(std::hypot(l[c].x() - l[0].x(), l[c].y() - l[0].y()), 1e-9);
      EXPECT_GT(l[c].z(), l[c - 1].z());
    }
    EXPECT_NEAR(lineLength(l), H, 2e-3 * H);
  }
  // Generatrices follow the base counter-clockwise seen from above, evenly spaced.
  const double step = 2 * kPi / 360;
  for (size_t m = 0; m + 1 < g.lines.size(); ++m) {
    const Vec3& a = g.lines[m][0];
    const Vec3& b = g.lines[m + 1][0];
    const double turn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.x() * b.x() + a.y() * b.y());
    EXPECT_NEAR(turn, step, 0.02 * step);
  }
  // Normals: horizontal and radial to within the polygon's half-angle.
  for (size_t m = 0; m < g.lines.size(); ++m) {
    for (size_t c = 0; c < g.lines[m].size(); ++c) {
      const Vec3& p = g.lines[m][c];
      const Vec3 radial = Vec3(p.x(), p.y(), 0).normalized();
      EXPECT_NEAR(g.normals[m][c].z(), 0.0, 1e-12);
      EXPECT_GT(g.normals[m][c].dot(radial), std::cos(kPi / 128));
    }
  }
  expectNoSharedPoints(g, 0.5 * 2 * kPi * R / 360);
}

TEST(IsovalueDecomposition, ConeGeneratricesRunUpTheSlant)
{
  const double r0 = 30, r1 = 15, H = 40;
  const OpenCase part = openPart(makeOpenCone(r0, r1, H, 160, 40));
  NullProgress progress;
  IsoDecompositionOptions opt;
  opt.pointsPerContour = 180;
  const IsoDecomposition d =
      decomposeByIsoValues(part.mesh, test::heightField(part.mesh, 1.0 / H), part.report.boundaryLoops[0],
                           &part.report.boundaryLoops[1], std::nullopt, opt, progress);
  const double slant = std::hypot(H, r0 - r1);
  ASSERT_EQ(d.generatrices.lines.size(), 180u);
  // Default spacing: the mean edge length.
  EXPECT_DOUBLE_EQ(d.levelSpacing, part.mesh.meanEdgeLength());
  for (const auto& l : d.generatrices.lines) {
    EXPECT_NEAR(lineLength(l), slant, 2e-3 * slant);
    EXPECT_NEAR(std::hypot(l.front().x(), l.front().y()), r0, 0.01 * r0);
    EXPECT_NEAR(std::hypot(l.back().x(), l.back().y()), r1, 0.01 * r1);
  }
  expectShapesMatch(d.generatrices);
  expectNoSharedPoints(d.generatrices, 1e-6);
}

TEST(IsovalueDecomposition, HemisphereGeneratricesAllEndAtThePole)
{
  const double R = 30;
  const TriangleMesh mesh = makeHemisphere(R, 128, 40);
  const MeshReport report = validateMesh(mesh);
  ASSERT_EQ(report.partClass, PartClass::Closed);
  NullProgress progress;
  IsoDecompositionOptions opt;
  opt.pointsPerContour = 200;
  const IsoDecomposition d = decomposeByIsoValues(
      mesh, test::hemisphereDistance(mesh, R), report.boundaryLoops[0], nullptr, std::nullopt, opt, progress);
  const Generatrices& g = d.generatrices;
  ASSERT_EQ(g.lines.size(), 200u);
  EXPECT_TRUE(g.hasClosurePoint);
  EXPECT_LT((g.closurePoint - Vec3(0, 0, R)).norm(), 1e-12);
  expectShapesMatch(g);
  for (size_t m = 0; m < g.lines.size(); ++m) {
    const Polyline& l = g.lines[m];
    EXPECT_LT((l.back() - Vec3(0, 0, R)).norm(), 1e-12);
    EXPECT_NEAR(l.front().z(), 0.0, 1e-12);
    EXPECT_NEAR(lineLength(l), 0.5 * kPi * R, 5e-3 * 0.5 * kPi * R);
    EXPECT_LT((g.normals[m].back() - Vec3::UnitZ()).norm(), 1e-9);
    // Along a meridian: every point's normal points away from the centre.
    for (size_t c = 0; c + 1 < l.size(); ++c) EXPECT_GT(g.normals[m][c].dot(l[c].normalized()), 0.999);
  }
  expectNoSharedPoints(g, 1e-9);
  // The last contour sits just below the pole, one level step away at most.
  const double lastLevel = d.contours.back().level;
  EXPECT_LT(lastLevel, 0.5 * kPi * R);
  EXPECT_GT(lastLevel, 0.5 * kPi * R - 2.0 * d.levelSpacing);
}

TEST(IsovalueDecomposition, GivenClosurePointIsUsed)
{
  const double R = 30;
  const TriangleMesh mesh = makeHemisphere(R, 64, 20);
  const MeshReport report = validateMesh(mesh);
  NullProgress progress;
  IsoDecompositionOptions opt;
  opt.pointsPerContour = 64;
  const Vec3 off(0, 0, R + 5);  // above the pole: its closest surface point is the pole
  const IsoDecomposition d = decomposeByIsoValues(mesh, test::hemisphereDistance(mesh, R),
                                                  report.boundaryLoops[0], nullptr, off, opt, progress);
  EXPECT_LT((d.generatrices.closurePoint - Vec3(0, 0, R)).norm(), 1e-9);
}

TEST(IsovalueDecomposition, TwoPeaksInsideTheClosureZoneAreNotBranches)
{
  // The distance field of a dome plus two bumps 4 mm either side of the pole: the top of the
  // field has three small peaks (the pole and the bumps), which the contours stop below.
  const double R = 30;
  const TriangleMesh mesh = makeHemisphere(R, 128, 40);
  const MeshReport report = validateMesh(mesh);
  std::vector<double> field = test::hemisphereDistance(mesh, R);
  for (size_t v = 0; v < mesh.vertexCount(); ++v)
    for (double side : {-4.0, 4.0})
      field[v] += 6.0 * std::exp(-(mesh.vertices[v] - Vec3(side, 0, R)).squaredNorm());
  NullProgress progress;
  IsoDecompositionOptions opt;
  opt.pointsPerContour = 90;
  opt.levelSpacing = 0.25;
  const IsoDecomposition d =
      decomposeByIsoValues(mesh, field, report.boundaryLoops[0], nullptr, std::nullopt, opt, progress);
  // (The smallest loops around the peaks may also be reported as specks.)
  bool warned = false;
  for (const auto& w : d.warnings)
    warned = warned || w.find("several maxima near its top") != std::string::npos;
  EXPECT_TRUE(warned) << ::testing::PrintToString(d.warnings);
  const Generatrices& g = d.generatrices;
  EXPECT_NEAR(std::abs(g.closurePoint.x()), 4.0, 1.0);
  for (const auto& l : g.lines) EXPECT_LT((l.back() - g.closurePoint).norm(), 1e-12);
  // The last contour kept still goes around the top, above the bumps' feet.
  EXPECT_GT(d.contours.back().level, 0.5 * kPi * R - 3.0);
}

TEST(IsovalueDecomposition, RefusesAPartThatSplits)
{
  const TriangleMesh a = makeOpenCylinder(5, 10, 40, 10);
  const TriangleMesh b = test::translated(makeOpenCylinder(5, 10, 40, 10), Vec3(20, 0, 5));
  const TriangleMesh mesh = test::merged(a, b);
  const MeshReport report = validateMesh(mesh);
  NullProgress progress;
  IsoDecompositionOptions opt;
  opt.levelSpacing = 0.5;
  try {
    decomposeByIsoValues(mesh, test::heightField(mesh), report.boundaryLoops[0], nullptr, std::nullopt, opt,
                         progress);
    FAIL() << "a splitting part was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the part splits into 2 branches at field value 5."), std::string::npos) << what;
    EXPECT_NE(what.find("about z = 5."), std::string::npos) << what;
    EXPECT_NE(what.find("narrower than a branch Spira plans on its own"), std::string::npos) << what;
    EXPECT_FALSE(e.hint().empty());
  }
}

TEST(IsovalueDecomposition, RefusesAContourThatRunsIntoAHole)
{
  // A cylinder with a window cut out half-way up: the contours there end on the window's edge.
  TriangleMesh mesh = makeOpenCylinder(10, 20, 32, 10);
  std::vector<Face> kept;
  for (const auto& f : mesh.faces) {
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < 3; ++k) c += mesh.vertices[f[k]] / 3.0;
    if (!(c.z() > 8 && c.z() < 12 && c.x() > 8)) kept.push_back(f);
  }
  mesh.faces = kept;
  const MeshReport report = validateMesh(mesh);
  ASSERT_EQ(report.boundaryLoops.size(), 3u);
  NullProgress progress;
  IsoDecompositionOptions opt;
  opt.levelSpacing = 1.0;
  try {
    decomposeByIsoValues(mesh, test::heightField(mesh, 1.0 / 20), report.boundaryLoops.front(),
                         &report.boundaryLoops.back(), std::nullopt, opt, progress);
    FAIL() << "an open contour was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("runs into a free edge"), std::string::npos) << e.what();
  }
}

TEST(IsovalueDecomposition, RejectsFieldsThatDoNotFit)
{
  const OpenCase part = openPart(makeOpenCylinder(10, 20, 32, 10));
  NullProgress progress;
  const IsoDecompositionOptions opt;
  const auto& lo = part.report.boundaryLoops[0];
  const auto* up = &part.report.boundaryLoops[1];
  EXPECT_THROW(
      decomposeByIsoValues(part.mesh, std::vector<double>(5, 0.0), lo, up, std::nullopt, opt, progress),
      InputError);
  // Decreasing from the lower edge to the upper one.
  EXPECT_THROW(decomposeByIsoValues(part.mesh, test::heightField(part.mesh, -1.0), lo, up, std::nullopt, opt,
                                    progress),
               InputError);
  IsoDecompositionOptions two = opt;
  two.pointsPerContour = 2;
  EXPECT_THROW(
      decomposeByIsoValues(part.mesh, test::heightField(part.mesh), lo, up, std::nullopt, two, progress),
      InputError);
}

TEST(IsovalueDecomposition, HonoursCancellation)
{
  const OpenCase part = openPart(makeOpenCylinder(10, 20, 32, 10));
  CallbackProgress progress;
  progress.cancel();
  EXPECT_THROW(
      decomposeByIsoValues(part.mesh, test::heightField(part.mesh), part.report.boundaryLoops[0],
                           &part.report.boundaryLoops[1], std::nullopt, IsoDecompositionOptions{}, progress),
      Cancelled);
}

TEST(IsovalueDecomposition, MeanFieldGradient)
{
  const TriangleMesh mesh = makeOpenCylinder(10, 20, 32, 10);
  EXPECT_NEAR(meanFieldGradient(mesh, test::heightField(mesh, 0.05)), 0.05, 1e-12);
  const TriangleMesh dome = makeHemisphere(10, 64, 16);
  // A distance field has unit gradient; the interpolated one is close to it.
  EXPECT_NEAR(meanFieldGradient(dome, test::hemisphereDistance(dome, 10)), 1.0, 0.01);
}

}  // namespace
}  // namespace spira
