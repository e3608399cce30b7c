// Straightening a path whose edge crossings CGAL put at the wrong ends: on a cylinder meshed with
// diagonals from (ring r, line j) to (ring r + 1, line j + 1), the geodesic up line j + 1 crosses
// each diagonal at its upper end; placed at the lower ends instead, the polyline runs up line j.
#include <gtest/gtest.h>

#include <cmath>

#include "decomposer_geodesic/path_straightening.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira::geodesic {
namespace {

constexpr int kSegments = 96, kRings = 40;

int vertexAt(int ring, int line)
{
  return ring * kSegments + (line % kSegments);
}

// The third vertex of each face on edge (a, b), by brute force: independent of CGAL's mesh.
std::array<int, 2> oppositeOf(const TriangleMesh& m, int a, int b)
{
  std::array<int, 2> out{-1, -1};
  size_t n = 0;
  for (const Face& f : m.faces) {
    const bool hasA = f[0] == a || f[1] == a || f[2] == a, hasB = f[0] == b || f[1] == b || f[2] == b;
    if (!hasA || !hasB || n == 2) continue;
    for (int v : f)
      if (v != a && v != b) out[n++] = v;
  }
  return out;
}

struct Case {
  TriangleMesh mesh = makeOpenCylinder(30.0, 60.0, kSegments, kRings);
  int line = 54;  // the crossings are put on this line; the geodesic runs up line + 1
  ExactPath path;

  // Crossing r at weight `upper` towards the upper end of diagonal r.
  explicit Case(double upper)
  {
    auto vertex = [&](int id) {
      PathPoint p;
      p.vertices = {id, -1, -1};
      p.weights = Vec3(1, 0, 0);
      p.position = mesh.vertices[size_t(id)];
      return p;
    };
    path.points.push_back(vertex(vertexAt(0, line + 1)));
    for (int r = 0; r < kRings; ++r) {
      PathPoint p;
      p.vertices = {vertexAt(r, line), vertexAt(r + 1, line + 1), -1};
      p.weights = Vec3(1.0 - upper, upper, 0.0);
      p.position =
          (1.0 - upper) * mesh.vertices[size_t(p.vertices[0])] + upper * mesh.vertices[size_t(p.vertices[1])];
      path.points.push_back(p);
    }
    path.points.push_back(vertex(vertexAt(kRings, line + 1)));
    path.length = 60.0;
  }
  StripMesh strip() const
  {
    StripMesh s;
    s.position = [this](int v) { return mesh.vertices[size_t(v)]; };
    s.opposite = [this](int a, int b) { return oppositeOf(mesh, a, b); };
    return s;
  }
};

TEST(PathStraightening, CrossingsAtTheWrongEndsComeBackToTheEdgeLine)
{
  Case c(0.0);
  ASSERT_NE(oppositeOf(c.mesh, vertexAt(3, c.line), vertexAt(4, c.line + 1))[1], -1);
  const double L = straightenPath(c.path, c.path.length, c.strip());
  EXPECT_NEAR(L, 60.0, 1e-9);
  const Vec3 base = c.mesh.vertices[size_t(vertexAt(0, c.line + 1))];
  double z = -1.0;
  for (const PathPoint& p : c.path.points) {
    EXPECT_LT(std::hypot(p.position.x() - base.x(), p.position.y() - base.y()), 1e-9);
    EXPECT_GE(p.position.z(), z);
    z = p.position.z();
  }
}

TEST(PathStraightening, ACrookedPathThroughTheStripBecomesItsStraightLine)
{
  // The same strip with the path's top moved half a segment round: the straight line of the
  // unfolded strip, of length hypot(60, half the segment's arc chord).
  Case c(0.3);
  const Vec3 a = c.mesh.vertices[size_t(vertexAt(kRings, c.line + 1))];
  const Vec3 b = c.mesh.vertices[size_t(vertexAt(kRings, c.line))];
  PathPoint& top = c.path.points.back();
  top.vertices = {vertexAt(kRings, c.line + 1), vertexAt(kRings, c.line), -1};
  top.weights = Vec3(0.5, 0.5, 0.0);
  top.position = 0.5 * (a + b);
  const double chord = 0.5 * (a - b).norm();
  const double expected = std::hypot(60.0, chord);
  const double L = straightenPath(c.path, expected, c.strip());
  EXPECT_NEAR(L, expected, 1e-9);
  // Unfolded, the strip is flat: line j at x = 0, line j + 1 at x = w (the segment's chord), and the
  // path x = w (1 - z / 120) meets diagonal r, x = w (z - 1.5 r) / 1.5, at z = 1.5 (r + 1) / 1.0125.
  int diagonals = 0;
  for (const PathPoint& p : c.path.points)
    for (int r = 0; r < kRings; ++r)
      if (p.vertices[0] == vertexAt(r, c.line) && p.vertices[1] == vertexAt(r + 1, c.line + 1)) {
        EXPECT_NEAR(p.position.z(), 1.5 * (r + 1) / (1.0 + 1.5 / 120.0), 1e-9) << "diagonal " << r;
        ++diagonals;
      }
  EXPECT_EQ(diagonals, kRings);
  // The ring edges between two diagonals were crossed too, and are now in the path.
  EXPECT_EQ(c.path.points.size(), size_t(2 + kRings + kRings - 1));
}

}  // namespace
}  // namespace spira::geodesic
