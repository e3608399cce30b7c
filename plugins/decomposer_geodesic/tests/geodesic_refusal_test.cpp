// The geodesic decomposer's refusals: parts whose geodesic generatrices no spiral can follow,
// told before the spiral is built and, where bounds on the lengths suffice, before the exact
// searches. Shapes made in code, with the lengths and the saddles known in closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <tbb/global_control.h>

#include "builtin_plugins.h"
#include "decomposer_geodesic/base_ring.h"
#include "decomposer_geodesic/geodesic_decomposition.h"
#include "decomposer_geodesic/length_spread.h"
#include "decomposer_geodesic/merged_neighbours.h"
#include "geodesic_shapes.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/planning/planner.h"

namespace spira::test {
namespace {

using namespace spira::geodesic;

// The corpus window: h 2 mm +/- 10 %, tolerance 0.5 % of h; bead 5.2 mm.
GeodesicOptions windowed(size_t n)
{
  GeodesicOptions o;
  o.pointsPerRevolution = n;
  o.window = {1.8, 2.2, 0.01};
  o.beadWidth = 5.2;
  return o;
}

GeodesicDecomposition decompose(const Part& part, const GeodesicOptions& options)
{
  NullProgress progress;
  const DecomposeInput in = part.input();
  return decomposeByGeodesics(part.mesh, in.lower, in.upper ? &*in.upper : nullptr, std::nullopt, nullptr,
                              options, progress);
}

// The InputError `f` throws, as "message | hint"; empty when it throws none.
template <class F>
std::string refusal(F f)
{
  try {
    f();
  } catch (const InputError& e) {
    return std::string(e.what()) + " | " + e.hint();
  }
  return "";
}

// A cylinder of radius R cut at the top by z = H + a cos(alpha). Unrolled (x = R alpha), the rim is
// y = H + a cos(x / R): from the base point at alpha = pi the nearest rim point is straight up, H - a
// away (no surface path rises less); from alpha = 0 it is min over x of the plane distance to the rim.
struct SlantCut {
  double R = 30.0, H = 60.0, a = 20.0;
  Part part(int segments, int rings) const
  {
    return makePart(makeTube([this](double, double) { return R; },
                             [this](double alpha) { return H + a * std::cos(alpha); }, segments, rings));
  }
  double shortest() const { return H - a; }
  double longest() const
  {
    double best = H + a;
    for (int k = 1; k <= 200000; ++k) {
      const double x = kPi * R * k / 200000.0;
      best = std::min(best, std::hypot(x, H + a * std::cos(x / R)));
    }
    return best;
  }
};

TEST(GeodesicLengthBounds, BracketTheExactGeodesicsOnASlantCutCylinder)
{
  const SlantCut cut;
  const Part part = cut.part(128, 40);
  const size_t n = 32;
  GeodesicOptions free;  // no window: the exact lengths, to hold the bounds against
  free.pointsPerRevolution = n;
  free.fillRounds = 0;
  const GeodesicDecomposition d = decompose(part, free);
  ASSERT_EQ(d.exactLengths.size(), n);
  // Independent truth for the extremes: the closed forms above (the mesh's chords of the 128-gon
  // are 0.01 % short of the arcs).
  EXPECT_NEAR(d.exactLengths[n / 2], cut.shortest(), 1e-6);
  EXPECT_NEAR(*std::max_element(d.exactLengths.begin(), d.exactLengths.end()), cut.longest(),
              2e-3 * cut.longest());

  const DecomposeInput in = part.input();
  const GeodesicMesh gm(part.mesh);
  const BaseRing ring(gm, in.lower);
  size_t ambiguous = 0;
  const std::vector<BasePoint> bases = ring.discretise(n, &ambiguous);
  GeodesicTarget target;
  target.upper = &*in.upper;
  const std::vector<LengthBounds> bounds = boundGeneratrixLengths(gm, bases, target);
  ASSERT_EQ(bounds.size(), n);
  for (size_t i = 0; i < n; ++i) {
    SCOPED_TRACE(i);
    EXPECT_LE(bounds[i].lower, d.exactLengths[i] + 1e-6);
    EXPECT_GE(bounds[i].upper, d.exactLengths[i] - 1e-6);
  }
  // Straight up the column at alpha = pi, the edge path is the geodesic itself.
  EXPECT_NEAR(bounds[n / 2].upper, cut.shortest(), 1e-6);
  // The bounds alone already tell the window cannot hold both: at alpha = 0 the straight segment to
  // the rim is at least 71.9 mm (the chord across the cylinder, shorter than the 76.2 mm path on
  // it) against at most 40 mm at alpha = pi.
  EXPECT_GT(bounds[0].lower / bounds[n / 2].upper, 1.7);
}

TEST(GeodesicLengthBounds, ADeepSlantCutIsRefusedBeforeTheExactSearches)
{
  // Longest over shortest 76.2 / 40 = 1.9 against (2.2 + 0.01) / (1.8 - 0.01) = 1.23.
  const Part part = SlantCut{}.part(128, 40);
  const std::string why = refusal([&] { decompose(part, windowed(32)); });
  ASSERT_FALSE(why.empty()) << "a deep slant cut was not refused";
  EXPECT_NE(why.find("Eq. 3.6"), std::string::npos) << why;
  EXPECT_NE(why.find("at least"), std::string::npos)
      << "refused on the bounds, before the exact searches: " << why;
  EXPECT_NE(why.find("at most 40.0 mm"), std::string::npos) << why;
  EXPECT_NE(why.find("--strategy isovalue"), std::string::npos) << why;
}

TEST(GeodesicLengthBounds, AShallowSlantCutFitsTheWindow)
{
  // 62 / 58 = 1.07: every layer fits 1.8 .. 2.2 mm.
  SlantCut shallow;
  shallow.a = 2.0;
  const GeodesicDecomposition d = decompose(shallow.part(128, 40), windowed(32));
  EXPECT_GE(d.generatrices.lines.size(), 32u);
  EXPECT_NEAR(*std::min_element(d.exactLengths.begin(), d.exactLengths.end()), shallow.shortest(), 1e-6);
}

TEST(GeodesicLengthBounds, ExactLengthsAreJudgedWithoutSlack)
{
  // Equal bounds are exact lengths: refused just past h_max / h_min with its tolerance, not before.
  const LayerWindow window{1.8, 2.2, 0.01};
  std::vector<BasePoint> bases(2);
  bases[1].point.position = Vec3(1.0, 0.0, 0.0);
  const double ratio = window.lengthRatio();
  EXPECT_NEAR(ratio, 2.21 / 1.79, 1e-12);
  EXPECT_TRUE(refusal([&] {
                requireLengthsFitWindow({{100.0, 100.0}, {100.0 * ratio * 0.999, 100.0 * ratio * 0.999}},
                                        bases, window, true);
              }).empty());
  EXPECT_FALSE(refusal([&] {
                 requireLengthsFitWindow({{100.0, 100.0}, {100.0 * ratio * 1.001, 100.0 * ratio * 1.001}},
                                         bases, window, true);
               }).empty());
  EXPECT_TRUE(refusal([&] {
                requireLengthsFitWindow({{100.0, 100.0}, {300.0, 300.0}}, bases, LayerWindow{}, true);
              }).empty())
      << "an unknown window refuses nothing";
}

// A vase with a waist: r(z) = R - d sin(pi z / H). Its profile is concave, so the surface is
// saddle-shaped everywhere (Gaussian curvature -r'' / (r (1 + r'^2)^2) < 0) and every inner vertex
// of its mesh has angles summing to more than 2 pi. Shortest paths bend at such vertices only:
// from base points on either side of a column they reach the rim through the same column vertex,
// then up the column together.
struct Waist {
  double R = 30.0, d = 8.0, H = 80.0;
  int segments = 24, rings = 40;
  double radius(double z) const { return R - d * std::sin(kPi * z / H); }
  Part part() const
  {
    return makePart(makeTube([this](double, double z) { return radius(z); }, [this](double) { return H; },
                             segments, rings));
  }
  // Length of the column (the mesh's meridian polyline) from height z to the rim.
  double columnFrom(double z) const
  {
    double s = 0.0;
    for (int j = 0; j < rings; ++j) {
      const double z0 = H * j / rings, z1 = H * (j + 1) / rings;
      const double seg = std::hypot(z1 - z0, radius(z1) - radius(z0));
      if (z1 <= z) continue;
      s += z0 >= z ? seg : seg * (z1 - z) / (z1 - z0);
    }
    return s;
  }
};

double angleSumAt(const TriangleMesh& m, int v)
{
  double sum = 0.0;
  for (const Face& f : m.faces)
    for (int k = 0; k < 3; ++k)
      if (f[size_t(k)] == v) {
        const Vec3 a = m.vertices[size_t(f[size_t((k + 1) % 3)])] - m.vertices[size_t(v)];
        const Vec3 b = m.vertices[size_t(f[size_t((k + 2) % 3)])] - m.vertices[size_t(v)];
        sum += std::atan2(a.cross(b).norm(), a.dot(b));
      }
  return sum;
}

TEST(GeodesicMergedNeighbours, OnAWaistedVaseGeodesicsShareColumnsUpToTheRim)
{
  const Waist vase;
  const Part part = vase.part();
  // The waist's vertices are saddles (ring 20 at z = 40, column 0).
  EXPECT_GT(angleSumAt(part.mesh, 20 * vase.segments), 2.0 * kPi + 1e-3);
  GeodesicOptions free;
  free.pointsPerRevolution = 360;
  free.fillRounds = 0;
  const GeodesicDecomposition d = decompose(part, free);
  const std::vector<Polyline>& lines = d.generatrices.lines;
  const double spacing = 2.0 * kPi * vase.R / 360.0;  // between base points
  const MergedNeighbours m =
      findMergedNeighbours(lines, 0, lines.size(), 0.01 * spacing, 5.2, std::nullopt, 0.0);
  ASSERT_GT(m.pairs, 0u);
  // The shared stretch runs up a column of vertices: in the meridian plane of one of the 24
  // columns, on the surface, and as long as that column from where the two meet to the last point
  // before the rim (the ends do not count), within one point spacing of the lines.
  const double columnAngle = 2.0 * kPi / vase.segments;
  const double alpha = angleOf(m.from);
  EXPECT_NEAR(std::remainder(alpha, columnAngle), 0.0, 1e-6) << "at angle " << alpha;
  EXPECT_NEAR(std::hypot(m.from.x(), m.from.y()), vase.radius(m.from.z()), 0.02);
  const Polyline& line = d.generatrices.lines[m.first];
  const double step = polylineLength(line) / double(line.size() - 1);
  EXPECT_NEAR(m.stretch, vase.columnFrom(m.from.z()) - step, step + 1e-6);
  EXPECT_NEAR(line.back().z(), vase.H, 1e-9);
}

PlanOutput planWith(const TriangleMesh& mesh, const std::string& strategy)
{
  const MeshReport report = validateMesh(mesh);
  PlanRequest request(mesh, report);
  request.decomposerId = strategy;
  NullProgress progress;
  return planPart(builtinRegistry(), request, progress);
}

TEST(GeodesicMergedNeighbours, TheStrategyTheRefusalNamesPlansTheWaistedVase)
{
  // At the planner's defaults (h 2 mm +/- 10 %, bead 5.2 mm, 360 generatrices) the geodesic
  // strategy is refused during its exact searches, before any spiral, and the iso-value strategy it
  // names lays the same vase inside the window (judged by the deposit check alone). Meshed 24
  // facets round, neighbouring geodesics share columns from the waist up (laid regardless, their
  // spiral puts 1,157 beads under earlier ones); 96 round, pairs pass a waist vertex on either side
  // 0.002 mm apart over 4 mm (their spiral lays beads of 0.38 mm there, and 136 beads fail the check).
  for (int segments : {24, 96}) {
    SCOPED_TRACE(segments);
    Waist waist;
    waist.segments = segments;
    const TriangleMesh vase = waist.part().mesh;
    const std::string why = refusal([&] { planWith(vase, "decomposer.geodesic"); });
    ASSERT_FALSE(why.empty());
    EXPECT_NE(why.find("generatrices meet"), std::string::npos) << why;
    EXPECT_NE(why.find("--strategy isovalue"), std::string::npos) << why;
    const PlanOutput iso = planWith(vase, "decomposer.isovalue");
    EXPECT_TRUE(iso.feasible()) << iso.deposits.summary();
  }
  // A cylinder still plans with geodesics: the checks refuse what no spiral follows, nothing else.
  const PlanOutput tube = planWith(makeOpenCylinder(30.0, 60.0, 96, 30), "decomposer.geodesic");
  EXPECT_TRUE(tube.feasible()) << tube.deposits.summary();
}

TEST(GeodesicMergedNeighbours, TheRefusalIsTheSameOnOneThreadAndOnMany)
{
  // No time budget and no order of completion in it: the same part gives the same words.
  const Part part = Waist{}.part();
  const std::string many = refusal([&] { decompose(part, windowed(360)); });
  std::string one;
  {
    const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = refusal([&] { decompose(part, windowed(360)); });
  }
  ASSERT_FALSE(many.empty());
  EXPECT_EQ(one, many);
}

TEST(GeodesicMergedNeighbours, DevelopableWallsPassBothChecks)
{
  // Cylinder and cone unroll into the plane: no vertex is a saddle, the geodesics are straight
  // lines of the development and all have one length (the height, the slant).
  const double R = 30.0, H = 60.0, r1 = 20.0;
  const GeodesicDecomposition c = decompose(makePart(makeOpenCylinder(R, H, 96, 30)), windowed(96));
  EXPECT_EQ(c.generatrices.lines.size(), 96u);
  for (double L : c.exactLengths) EXPECT_NEAR(L, H, 1e-6);
  const GeodesicDecomposition k = decompose(makePart(makeOpenCone(R, r1, H, 96, 30)), windowed(96));
  EXPECT_EQ(k.generatrices.lines.size(), 96u);
  for (double L : k.exactLengths) EXPECT_NEAR(L, std::hypot(H, R - r1), 1e-6);
}

TEST(GeodesicMergedNeighbours, LinesMeetingOnlyAtTheClosurePointDoNotCount)
{
  // 360 straight meridians of a flat disc of radius 40 mm, 40 points each, all ending at its centre:
  // at radius r neighbours lie 2 pi r / 360 apart, under 1 % of their base spacing (0.0070 mm)
  // only within 0.4 mm of the centre, where the inner point nearest to it (at 1.03 mm) stays clear;
  // at 1 % of a bead (0.052 mm) they meet from r = 2.98 mm in, which the closure's bead excludes.
  const size_t n = 360, points = 40;
  const double R = 40.0;
  std::vector<Polyline> lines(n);
  for (size_t i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * double(i) / double(n);
    for (size_t k = 0; k < points; ++k) {
      const double r = R * (1.0 - double(k) / double(points - 1));
      lines[i].push_back(Vec3(r * std::cos(a), r * std::sin(a), 0.0));
    }
  }
  const Vec3 centre = Vec3::Zero();
  const double spacing = 2.0 * R * std::sin(kPi / double(n));
  EXPECT_EQ(findMergedNeighbours(lines, 0, n, 0.01 * spacing, 0.0, centre, 5.2).pairs, 0u);
  EXPECT_EQ(findMergedNeighbours(lines, 0, n, 0.052, 0.0, centre, 5.2).pairs, 0u);
  // Without the closure's bead every pair meets over the inner points within 2.98 mm of the centre
  // (r sin(1 degree) < 0.052 mm): those at 2.05 and 1.03 mm, a stretch of 1.03 mm.
  const MergedNeighbours m = findMergedNeighbours(lines, 0, n, 0.052, 0.0, std::nullopt, 0.0);
  EXPECT_EQ(m.pairs, n);
  const double step = R / double(points - 1);
  EXPECT_NEAR(m.from.norm(), 2.0 * step, 1e-9);
  EXPECT_NEAR(m.stretch, step, 1e-9);
}

TEST(GeodesicMergedNeighbours, AClosedPartsGeneratricesMeetOnlyAtItsClosurePoint)
{
  // A hemisphere's meridians all end at the pole: within a bead of it they are closer than any
  // gap, and that is the closure the spiral folds, not a merge.
  const double R = 40.0;
  const GeodesicDecomposition d = decompose(makePart(makeHemisphere(R, 96, 24)), windowed(96));
  EXPECT_EQ(d.generatrices.lines.size(), 96u);
  for (double L : d.exactLengths) EXPECT_NEAR(L, 0.5 * kPi * R, 0.01 * R);
}

}  // namespace
}  // namespace spira::test
