#include <cmath>

#include <gtest/gtest.h>

#include "spira/base/units.h"
#include "spira/mesh/corner_normals.h"
#include "spira/mesh/mesh_primitives.h"

using namespace spira;

namespace {

constexpr int kSegments = 32;

int vertexAt(const TriangleMesh& m, const Vec3& p)
{
  for (size_t v = 0; v < m.vertices.size(); ++v)
    if ((m.vertices[v] - p).norm() < 1e-9) return static_cast<int>(v);
  return -1;
}

void addFace(TriangleMesh& m, int a, int b, int c)
{
  Face f{a, b, c};
  m.faces.push_back(f);
  if (m.faceNormal(m.faces.size() - 1).z() < 0.0) std::swap(m.faces.back()[1], m.faces.back()[2]);
}

// A tube wall of radius R standing on a flat flange (R..2R at z = 0), the flange cut the way CAD
// exporters cut planar faces: one wall vertex (angle 0) carries a fan of four large triangles.
TriangleMesh tubeOnFannedFlange(double R, double H)
{
  TriangleMesh m = makeOpenCylinder(R, H, kSegments, 1);
  std::vector<int> in(kSegments), out(kSegments);
  for (int i = 0; i < kSegments; ++i) {
    const double a = 2.0 * kPi * i / kSegments;
    in[i] = vertexAt(m, Vec3(R * std::cos(a), R * std::sin(a), 0.0));
    out[i] = static_cast<int>(m.vertices.size());
    m.vertices.emplace_back(2 * R * std::cos(a), 2 * R * std::sin(a), 0.0);
  }
  for (int k = 0; k < 4; ++k) addFace(m, in[0], out[k], out[k + 1]);
  for (int i = 0; i < 4; ++i) addFace(m, in[i], in[i + 1], out[4]);
  for (int i = 4; i < kSegments; ++i) {
    const int j = (i + 1) % kSegments;
    addFace(m, in[i], in[j], out[j]);
    addFace(m, in[i], out[j], out[i]);
  }
  return m;
}

}  // namespace

TEST(CornerNormals, WallNormalsStayRadialWhereAFannedFlangeMeetsTheWall)
{
  const double R = 10.0;
  const TriangleMesh m = tubeOnFannedFlange(R, 20.0);
  ASSERT_EQ(m.faces.size(), size_t(2 * kSegments + 8 + 2 * (kSegments - 4)));
  const std::vector<Vec3> n = cornerNormals(m);
  ASSERT_EQ(n.size(), 3 * m.faces.size());
  const int fanVertex = vertexAt(m, Vec3(R, 0, 0));
  int wallCornersAtFan = 0;
  for (size_t f = 0; f < m.faces.size(); ++f) {
    const bool flange = std::abs(m.faceNormal(f).z()) > 0.5;
    for (int k = 0; k < 3; ++k) {
      const Vec3& c = n[3 * f + k];
      const Vec3& p = m.vertices[m.faces[f][k]];
      EXPECT_NEAR(c.norm(), 1.0, 1e-12);
      if (flange) {
        EXPECT_NEAR(c.z(), 1.0, 1e-12);
        continue;
      }
      // On a wall face: the ring's two neighbouring faces are symmetric about the radial direction.
      EXPECT_NEAR(c.z(), 0.0, 1e-12) << "face " << f << " corner " << k;
      EXPECT_NEAR(c.dot(Vec3(p.x(), p.y(), 0).normalized()), 1.0, 1e-12);
      if (m.faces[f][k] == fanVertex) ++wallCornersAtFan;
    }
  }
  EXPECT_GE(wallCornersAtFan, 1);
  // The area-weighted vertex normal there leans onto the flange: what the corner normals avoid.
  const Vec3 vertexNormal = m.vertexNormals()[size_t(fanVertex)];
  EXPECT_GT(vertexNormal.z(), std::sin(30.0 * kPi / 180.0));
}

TEST(CornerNormals, CurvedSurfaceIsSmoothAndIndependentOfTheCut)
{
  // On a hemisphere every face meets its neighbours at a few degrees: nothing is a crease, and the
  // corner normals of all faces around a vertex agree: one normal per vertex, within the faces'
  // own spread (half a segment, 3.75 degrees, and half a ring) of the radial direction.
  const TriangleMesh m = makeHemisphere(10.0, 48, 12);
  const std::vector<Vec3> n = cornerNormals(m);
  std::vector<Vec3> first(m.vertices.size(), Vec3::Zero());
  for (size_t f = 0; f < m.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = m.faces[f][k];
      const Vec3 radial = m.vertices[v].normalized();
      EXPECT_GT(n[3 * f + k].dot(radial), std::cos(5.0 * kPi / 180.0));
      if (first[v].isZero()) first[v] = n[3 * f + k];
      EXPECT_NEAR((n[3 * f + k] - first[v]).norm(), 0.0, 1e-12);
    }
  // A crease angle below the faces' dihedral angles keeps every face its own normal.
  const std::vector<Vec3> flat = cornerNormals(m, 0.1);
  for (size_t f = 0; f < m.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(flat[3 * f + k].dot(m.faceNormal(f)), 1.0, 1e-12);
}
