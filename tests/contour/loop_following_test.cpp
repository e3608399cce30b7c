#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "contour_shapes.h"
#include "spira/base/units.h"
#include "spira/contour/generatrix_chain.h"
#include "spira/contour/isovalue_decomposition.h"
#include "spira/contour/loop_following.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"

namespace spira {
namespace {

// A tube of radius R around the Z axis cut by the planes z = a x and z = H + a x: every section
// z - a x = c is the same ellipse moved up, so the field f = z - a x (exact at the vertices) has
// congruent contours, and resampling each by arc length on its own links points straight up, at
// up to atan(a) from the contours' normals. On the unrolled wall (s = R phi, z) the surface
// gradient of f is (a sin(phi), 1), so the orthogonal trajectories solve dphi/dz = (a / R) sin(phi):
// tan(phi / 2) = tan(phi0 / 2) exp(a (z - z0) / R).
TriangleMesh slantedCutTube(double R, double H, double a, int segments, int rings)
{
  TriangleMesh m;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const double phi = 2.0 * kPi * i / segments;
      const double x = R * std::cos(phi), y = R * std::sin(phi);
      m.vertices.emplace_back(x, y, a * x + H * j / rings);
    }
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const int i1 = (i + 1) % segments;
      const int p = j * segments + i, q = j * segments + i1, r = (j + 1) * segments + i1,
                s = (j + 1) * segments + i;
      m.faces.push_back({p, q, r});
      m.faces.push_back({p, r, s});
    }
  return m;
}

double wrapAngle(double d)
{
  while (d > kPi) d -= 2.0 * kPi;
  while (d < -kPi) d += 2.0 * kPi;
  return d;
}

TEST(LoopFollowing, SlantedCutTubeGeneratricesAreTheFieldsOrthogonalTrajectories)
{
  const double R = 20.0, H = 12.0, a = 0.4;
  const TriangleMesh mesh = slantedCutTube(R, H, a, 256, 24);
  const MeshReport report = validateMesh(mesh);
  ASSERT_EQ(report.partClass, PartClass::Open);
  const BoundaryLoop* lower = &report.boundaryLoops[0];
  const BoundaryLoop* upper = &report.boundaryLoops[1];
  if (mesh.vertices[lower->vertices[0]].z() - a * mesh.vertices[lower->vertices[0]].x() > 1.0)
    std::swap(lower, upper);
  std::vector<double> field(mesh.vertexCount());
  for (size_t v = 0; v < field.size(); ++v) field[v] = mesh.vertices[v].z() - a * mesh.vertices[v].x();
  IsoDecompositionOptions opt;
  opt.pointsPerContour = 180;
  opt.levelSpacing = 0.5;
  NullProgress progress;
  const IsoDecomposition d = decomposeByIsoValues(mesh, field, *lower, upper, std::nullopt, opt, progress);
  const Generatrices& g = d.generatrices;
  ASSERT_EQ(g.lines.size(), 180u);

  // Shear: the angle between each generatrix segment and the exact contour normal, the surface
  // gradient a sin(phi) e_phi + e_z at the segment's midpoint. Even arc-length resampling gives
  // vertical segments, up to atan(0.4) = 21.8 degrees off; the least-shear links stay within 4 (2.7
  // today: what is left is the spacing term's pull).
  double maxShear = 0.0;
  for (const Polyline& l : g.lines)
    for (size_t c = 0; c + 1 < l.size(); ++c) {
      const Vec3 mid = 0.5 * (l[c] + l[c + 1]);
      const double phi = std::atan2(mid.y(), mid.x());
      const Vec3 ePhi(-std::sin(phi), std::cos(phi), 0.0);
      const Vec3 gradient = a * std::sin(phi) * ePhi + Vec3::UnitZ();
      const Vec3 seg = l[c + 1] - l[c];
      const double cosine = seg.dot(gradient) / (seg.norm() * gradient.norm());
      maxShear = std::max(maxShear, std::acos(std::min(1.0, cosine)));
    }
  EXPECT_LT(maxShear, 4.0 * kPi / 180.0) << "max shear " << maxShear * 180.0 / kPi << " deg";

  // Each generatrix follows the trajectory from its base point: tan(phi / 2) grows as
  // exp(a dz / R), which carries the points up to 4.2 mm sideways (towards phi = pi) over the 12 mm;
  // the spacing term holds them back by under 0.4 mm (0.3 today), about half a point spacing.
  double maxError = 0.0, maxDrift = 0.0;
  for (const Polyline& l : g.lines) {
    const double phi0 = std::atan2(l.front().y(), l.front().x());
    for (const Vec3& p : l) {
      const double phi = std::atan2(p.y(), p.x());
      const double exact = 2.0 * std::atan(std::tan(0.5 * phi0) * std::exp(a * (p.z() - l.front().z()) / R));
      maxError = std::max(maxError, R * std::abs(wrapAngle(phi - exact)));
      maxDrift = std::max(maxDrift, R * std::abs(wrapAngle(exact - phi0)));
    }
  }
  EXPECT_GT(maxDrift, 4.0);  // the trajectories do bend: straight lines would be off by this much
  EXPECT_LT(maxError, 0.4) << "mm off the exact trajectory";
}

// On congruent contours stacked straight up (a plain cylinder) the correspondence is the vertical
// translation, exactly what even arc-length resampling gives.
TEST(LoopFollowing, CylinderContoursLinkStraightUp)
{
  const double R = 15.0, H = 20.0;
  const TriangleMesh mesh = makeOpenCylinder(R, H, 96, 20);
  const std::vector<double> field = test::heightField(mesh);
  const IsoLevel lo = extractIsoContour(mesh, field, 4.5), hi = extractIsoContour(mesh, field, 6.2);
  ASSERT_EQ(lo.contours.size(), 1u);
  ASSERT_EQ(hi.contours.size(), 1u);
  const ResampledLoop base = resampleLoop(mesh, lo.contours[0], 120, 3.7);
  const ResampledLoop next = resampleLoopFollowing(mesh, hi.contours[0], base.positions());
  ASSERT_EQ(next.points.size(), 120u);
  for (size_t k = 0; k < 120; ++k) {
    const Vec3 d = next.points[k].position - base.points[k].position;
    EXPECT_NEAR(d.z(), 1.7, 1e-9);
    EXPECT_LT(std::hypot(d.x(), d.y()), 1e-9) << k;
    EXPECT_GE(next.points[k].face, 0);
  }
}

// A round contour followed by a wavy one (it rises and falls by 0.7 mm three times around): points
// keep their order and turning sense, no two closer than minSpacing of the even spacing, and each
// lands near the foot of its partner.
TEST(LoopFollowing, OrderIsKeptOnAWavyContour)
{
  const double R = 15.0;
  const TriangleMesh mesh = makeOpenCylinder(R, 10.0, 128, 10);
  // A field whose contours below z = 5 are circles and whose 6.5 contour is wavy.
  std::vector<double> field(mesh.vertexCount());
  for (size_t v = 0; v < field.size(); ++v) {
    const Vec3& p = mesh.vertices[v];
    const double phi = std::atan2(p.y(), p.x());
    field[v] = p.z() - 0.4 * std::max(0.0, p.z() - 5.0) * std::cos(3.0 * phi);
  }
  const IsoLevel lo = extractIsoContour(mesh, field, 4.6), hi = extractIsoContour(mesh, field, 6.5);
  ASSERT_EQ(hi.contours.size(), 1u);
  const size_t n = 90;
  const ResampledLoop base = resampleLoop(mesh, lo.contours[0], n);
  const LoopFollowingOptions options;
  const ResampledLoop next = resampleLoopFollowing(mesh, hi.contours[0], base.positions(), options);
  ASSERT_EQ(next.points.size(), n);
  const double even = next.length / static_cast<double>(n);
  double turned = 0.0;
  for (size_t k = 0; k < n; ++k) {
    const Vec3& p = next.points[k].position;
    const Vec3& q = next.points[(k + 1) % n].position;
    EXPECT_GT((q - p).norm(), options.minSpacing * even * 0.99) << k;
    turned += wrapAngle(std::atan2(q.y(), q.x()) - std::atan2(p.y(), p.x()));
    // Within a spacing or so of straight above its partner.
    const double dphi = wrapAngle(std::atan2(p.y(), p.x()) -
                                  std::atan2(base.points[k].position.y(), base.points[k].position.x()));
    EXPECT_LT(R * std::abs(dphi), 2.0 * even) << k;
  }
  EXPECT_NEAR(turned, 2.0 * kPi, 1e-9);  // once around, counter-clockwise as the base
}

TEST(LoopFollowing, ShortestLinkedGeneratrixPicksTheShortestChain)
{
  // Three contours of four points; chain 2 is the shortest, ties would go to the lowest index.
  const std::vector<std::vector<Vec3>> contours = {
      {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0)},
      {Vec3(0, 0, 2), Vec3(1, 0, 1.5), Vec3(2, 0, 1), Vec3(3, 0, 1.2)},
      {Vec3(0, 0, 4), Vec3(1, 0, 3), Vec3(2, 0, 2), Vec3(3, 0, 3)},
  };
  const PrincipalGeneratrix p = shortestLinkedGeneratrix(contours, std::nullopt);
  EXPECT_EQ(p.index, std::vector<size_t>({2, 2, 2}));
  EXPECT_DOUBLE_EQ(p.length, 2.0);
  const PrincipalGeneratrix closed = shortestLinkedGeneratrix(contours, Vec3(0, 0, 5));
  EXPECT_EQ(closed.index[0], 0u);  // 4 + 1 against 2 + 3.6 for chain 2
  EXPECT_DOUBLE_EQ(closed.length, 5.0);
}

}  // namespace
}  // namespace spira
