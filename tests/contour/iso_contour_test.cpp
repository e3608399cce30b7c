#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "contour_shapes.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/contour/contour_loop.h"
#include "spira/contour/iso_contour.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"

namespace spira {
namespace {

using test::heightField;

// Every segment's ends lie in its face: barycentric weights rebuild the position.
void expectSegmentsInFaces(const TriangleMesh& mesh, const IsoContour& c)
{
  const size_t m = c.points.size();
  ASSERT_EQ(c.segmentFaces.size(), c.closed ? m : m - 1);
  for (size_t i = 0; i < c.segmentFaces.size(); ++i) {
    for (size_t j : {i, (i + 1) % m}) {
      const Vec3 w = c.barycentricIn(mesh, j, c.segmentFaces[i]);
      const Face& f = mesh.faces[c.segmentFaces[i]];
      EXPECT_NEAR(w.sum(), 1.0, 1e-12);
      EXPECT_GE(w.minCoeff(), 0.0);
      const Vec3 x = w[0] * mesh.vertices[f[0]] + w[1] * mesh.vertices[f[1]] + w[2] * mesh.vertices[f[2]];
      EXPECT_LT((x - c.points[j].position).norm(), 1e-12);
    }
  }
}

TEST(IsoContour, CylinderHeightLevelsAreThePolygonAtThatHeight)
{
  const double R = 20, H = 50;
  const int N = 96, rings = 25;
  const TriangleMesh mesh = makeOpenCylinder(R, H, N, rings);
  const std::vector<double> levels{0.7, 13.3, 24.999, 37.1, 49.9};
  const auto result = extractIsoContours(mesh, heightField(mesh), levels);
  ASSERT_EQ(result.size(), levels.size());
  const double perimeter = 2 * N * R * std::sin(kPi / N);
  for (size_t k = 0; k < levels.size(); ++k) {
    ASSERT_EQ(result[k].contours.size(), 1u) << levels[k];
    const IsoContour& c = result[k].contours[0];
    EXPECT_TRUE(c.closed);
    EXPECT_EQ(c.level, levels[k]);
    // One crossing on each vertical edge and each diagonal of the band.
    EXPECT_EQ(c.points.size(), 2u * N);
    for (const auto& p : c.points) {
      EXPECT_NEAR(p.position.z(), levels[k], 1e-9);
      EXPECT_LT(test::distanceToPolygon(p.position, R, N), 1e-9);
    }
    EXPECT_NEAR(c.length(), perimeter, 1e-9 * perimeter);
    EXPECT_NEAR(c.length(), 2 * kPi * R, 1e-3 * 2 * kPi * R);
    // Higher field on the left seen from outside: counter-clockwise seen from above.
    EXPECT_TRUE(isCounterClockwise(c, Vec3::UnitZ()));
    expectSegmentsInFaces(mesh, c);
  }
}

TEST(IsoContour, LevelThroughVerticesGivesTheRingItself)
{
  const double R = 20, H = 50;
  const int N = 64, rings = 10;
  const TriangleMesh mesh = makeOpenCylinder(R, H, N, rings);
  const double ringZ = 3 * H / rings;  // exactly the height of ring 3
  const IsoLevel l = extractIsoContour(mesh, heightField(mesh), ringZ);
  ASSERT_EQ(l.contours.size(), 1u);
  const IsoContour& c = l.contours[0];
  ASSERT_EQ(c.points.size(), static_cast<size_t>(N));  // repeats at the vertices merged
  for (const auto& p : c.points) {
    EXPECT_TRUE(p.onVertex());
    EXPECT_NEAR(std::hypot(p.position.x(), p.position.y()), R, 1e-9);
    EXPECT_NEAR(p.position.z(), ringZ, 1e-12);
  }
  EXPECT_TRUE(isCounterClockwise(c, Vec3::UnitZ()));
  expectSegmentsInFaces(mesh, c);
  // The top rim (field maximum on a whole ring) is still found, the bottom one (minimum) is not.
  EXPECT_EQ(extractIsoContour(mesh, heightField(mesh), H).contours.size(), 1u);
  EXPECT_TRUE(extractIsoContour(mesh, heightField(mesh), 0.0).contours.empty());
  EXPECT_TRUE(extractIsoContour(mesh, heightField(mesh), H + 1).contours.empty());
}

TEST(IsoContour, HemisphereDistanceGivesLatitudeCircles)
{
  const double R = 30;
  const int N = 128, rings = 32;
  const TriangleMesh mesh = makeHemisphere(R, N, rings);
  const std::vector<double> field = test::hemisphereDistance(mesh, R);
  const double dphi = 0.5 * kPi / rings;
  // On ring latitudes the contour runs through the ring's vertices: on the analytic circle. (The
  // field's values on one ring differ in the last bits, so the level is the ring's smallest one
  // and crossings land within rounding of the vertices.)
  for (int i : {1, 9, 20, 31}) {
    const double phi = i * dphi;
    double level = R * phi + 1.0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
      if (std::abs(field[v] - R * phi) < 1e-9) level = std::min(level, field[v]);
    const IsoLevel l = extractIsoContour(mesh, field, level);
    ASSERT_EQ(l.contours.size(), 1u);
    EXPECT_GE(l.contours[0].points.size(), static_cast<size_t>(N));
    for (const auto& p : l.contours[0].points) {
      EXPECT_NEAR(p.position.z(), R * std::sin(phi), 1e-9);
      EXPECT_NEAR(std::hypot(p.position.x(), p.position.y()), R * std::cos(phi), 1e-9);
    }
  }
  // Between rings the points interpolate the field linearly along the crossed edges: the height
  // is exactly the interpolated one and within the chordal error of the latitude circle.
  for (double frac : {0.25, 0.5, 0.8}) {
    for (int i : {0, 12, 30}) {
      const double phi = (i + frac) * dphi;
      const IsoLevel l = extractIsoContour(mesh, field, R * phi);
      ASSERT_EQ(l.contours.size(), 1u);
      const IsoContour& c = l.contours[0];
      const double zLerp = (1 - frac) * R * std::sin(i * dphi) + frac * R * std::sin((i + 1) * dphi);
      const double chordal = R * dphi * dphi / 8 + R * (1 - std::cos(kPi / N));
      for (const auto& p : c.points) {
        EXPECT_NEAR(p.position.z(), zLerp, 1e-9);
        const double offCircle = std::hypot(std::hypot(p.position.x(), p.position.y()) - R * std::cos(phi),
                                            p.position.z() - R * std::sin(phi));
        EXPECT_LT(offCircle, chordal);
      }
      EXPECT_NEAR(c.length(), 2 * kPi * R * std::cos(phi), 2 * kPi * chordal);
      EXPECT_TRUE(isCounterClockwise(c, Vec3::UnitZ()));
      expectSegmentsInFaces(mesh, c);
    }
  }
  // Just below the pole a tiny loop remains; at the pole's value the loop shrinks to nothing.
  EXPECT_EQ(extractIsoContour(mesh, field, 0.5 * kPi * R - 0.1).contours.size(), 1u);
  EXPECT_TRUE(extractIsoContour(mesh, field, 0.5 * kPi * R).contours.empty());
}

TEST(IsoContour, OrientationFollowsTheFieldNotTheAxis)
{
  const TriangleMesh mesh = makeOpenCylinder(10, 20, 48, 8);
  std::vector<double> down = heightField(mesh, -1.0);
  const IsoLevel l = extractIsoContour(mesh, down, -7.3);
  ASSERT_EQ(l.contours.size(), 1u);
  IsoContour c = l.contours[0];
  // Field growing downwards: the higher side is below, so the loop turns the other way.
  EXPECT_FALSE(isCounterClockwise(c, Vec3::UnitZ()));
  EXPECT_TRUE(orientCounterClockwise(c, Vec3::UnitZ()));
  EXPECT_TRUE(isCounterClockwise(c, Vec3::UnitZ()));
  EXPECT_FALSE(orientCounterClockwise(c, Vec3::UnitZ()));
  expectSegmentsInFaces(mesh, c);
}

TEST(IsoContour, FlatForkGivesOpenPolylinesAcrossTheStrip)
{
  const TriangleMesh mesh = test::flatFork();
  // A constant field at the level: every vertex counts as above it, so nothing is crossed.
  EXPECT_TRUE(extractIsoContour(mesh, heightField(mesh), 0.0).contours.empty());
  std::vector<double> y;
  for (const auto& v : mesh.vertices) y.push_back(v.y());
  const IsoLevel low = extractIsoContour(mesh, y, 2.5);
  ASSERT_EQ(low.contours.size(), 1u);
  EXPECT_FALSE(low.contours[0].closed);
  EXPECT_NEAR(low.contours[0].length(), 6.0, 1e-12);
  // Faces up, field growing along +y: the higher side on the left means running along +x.
  EXPECT_NEAR(low.contours[0].points.front().position.x(), -3.0, 1e-12);
  EXPECT_NEAR(low.contours[0].points.back().position.x(), 3.0, 1e-12);
  expectSegmentsInFaces(mesh, low.contours[0]);
  const IsoLevel high = extractIsoContour(mesh, y, 7.25);
  ASSERT_EQ(high.contours.size(), 2u);
  for (const auto& c : high.contours) {
    EXPECT_FALSE(c.closed);
    EXPECT_NEAR(c.length(), 2.0, 1e-12);
    EXPECT_LT(c.points.front().position.x(), c.points.back().position.x());
    expectSegmentsInFaces(mesh, c);
  }
}

TEST(IsoContour, BoundaryLoopAsContour)
{
  const TriangleMesh mesh = makeOpenCylinder(15, 30, 40, 6);
  const MeshReport report = validateMesh(mesh);
  ASSERT_EQ(report.boundaryLoops.size(), 2u);
  const IsoContour lower = contourFromBoundaryLoop(mesh, report.boundaryLoops[0].vertices, 0.0, true);
  const IsoContour upper = contourFromBoundaryLoop(mesh, report.boundaryLoops[1].vertices, 30.0, false);
  // Both turn like the iso-contours in between: counter-clockwise seen from above.
  EXPECT_TRUE(isCounterClockwise(lower, Vec3::UnitZ()));
  EXPECT_TRUE(isCounterClockwise(upper, Vec3::UnitZ()));
  EXPECT_EQ(lower.points.size(), 40u);
  EXPECT_NEAR(upper.points[0].position.z(), 30.0, 1e-12);
  expectSegmentsInFaces(mesh, lower);
  expectSegmentsInFaces(mesh, upper);
  // The same loop asked the other way round runs the other way.
  const IsoContour flipped = contourFromBoundaryLoop(mesh, report.boundaryLoops[0].vertices, 0.0, false);
  EXPECT_FALSE(isCounterClockwise(flipped, Vec3::UnitZ()));
  expectSegmentsInFaces(mesh, flipped);
  EXPECT_THROW(contourFromBoundaryLoop(mesh, {0, 1}, 0.0, true), InputError);
  EXPECT_THROW(contourFromBoundaryLoop(mesh, {0, 1, 2 * 40 + 5}, 0.0, true), InputError);
}

TEST(IsoContour, RejectsBadFieldsAndLevels)
{
  const TriangleMesh mesh = makeOpenCylinder(10, 20, 16, 4);
  std::vector<double> f = heightField(mesh);
  EXPECT_THROW(extractIsoContours(mesh, std::vector<double>(3, 0.0), {1.0}), InputError);
  EXPECT_THROW(extractIsoContours(mesh, f, {5.0, 2.0}), InputError);
  f[7] = std::nan("");
  EXPECT_THROW(extractIsoContours(mesh, f, {5.0}), InputError);
  EXPECT_TRUE(extractIsoContours(mesh, heightField(mesh), {}).empty());
}

TEST(IsoContour, NonManifoldEdgeIsReported)
{
  // Three fins on one edge (0,1) along z, field = z: the iso-line crosses that edge in three faces.
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0.5), Vec3(-1, 0, 0.5), Vec3(0, 1, 0.5)};
  m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 4, 1}};
  EXPECT_THROW(extractIsoContour(m, heightField(m), 0.25), InputError);
}

}  // namespace
}  // namespace spira
