// Spira's OBJ reader on well-formed files: the statements and corner forms exporters write,
// checked against geometry known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "io_test_util.h"
#include "obj_bytes.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"

namespace spira::test {
namespace {

// The six outward quads of the unit cube, each corner written through `corner` (1-based index).
template <class Corner>
std::string cubeQuads(Corner corner)
{
  const int quads[6][4] = {{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5},
                           {3, 4, 8, 7}, {1, 5, 8, 4}, {2, 3, 7, 6}};
  std::string s;
  for (const auto& q : quads) {
    s += "f";
    for (int v : q) s += " " + corner(v);
    s += "\n";
  }
  return s;
}

TEST(ObjReader, UnitCubeOfQuadsIsTwelveTrianglesOfAreaSixAndClosed)
{
  const ObjData obj = parseObjBytes(kCubeVertices + cubeQuads([](int v) { return std::to_string(v); }));
  ASSERT_EQ(obj.mesh.vertexCount(), 8u);
  ASSERT_EQ(obj.mesh.faceCount(), 12u);
  EXPECT_EQ(obj.polygonFaces, 6u);
  EXPECT_NEAR(obj.mesh.area(), 6.0, 1e-12);
  EXPECT_NEAR(signedVolume(obj.mesh), 1.0, 1e-12);  // outward faces enclose the unit volume
  const MeshReport report = validateMesh(obj.mesh);
  EXPECT_TRUE(report.boundaryLoops.empty());
  EXPECT_TRUE(report.issues.empty());
  EXPECT_EQ(report.componentCount, 1u);
  ASSERT_EQ(obj.warnings.size(), 1u);
  EXPECT_EQ(obj.warnings[0], "6 faces in 'test.obj' with more than three corners split into triangles");
}

TEST(ObjReader, NegativeIndicesCountBackFromTheLastVertexRead)
{
  const ObjData positive = parseObjBytes(kCubeVertices + cubeQuads([](int v) { return std::to_string(v); }));
  const ObjData negative =
      parseObjBytes(kCubeVertices + cubeQuads([](int v) { return std::to_string(v - 9); }));
  EXPECT_EQ(negative.mesh.faces, positive.mesh.faces);
  // Relative to the vertices read so far, not to the file's total: each triangle's -3 -2 -1 are
  // the three vertices just above it.
  const ObjData strip = parseObjBytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 1 1 0\nf -3 -1 -2\n");
  ASSERT_EQ(strip.mesh.faceCount(), 2u);
  EXPECT_EQ(strip.mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(strip.mesh.faces[1], (Face{1, 3, 2}));
  EXPECT_NEAR(strip.mesh.area(), 1.0, 1e-12);
}

TEST(ObjReader, EveryCornerFormNamesTheSameVertex)
{
  const std::string base = "v 0 0 0\nv 2 0 0\nv 0 2 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n";
  for (const char* face : {"f 1 2 3", "f 1/1 2/2 3/3", "f 1//1 2//1 3//1", "f 1/1/1 2/2/1 3/3/1",
                           "f -3/-3/-1 -2/-2/-1 -1/-1/-1", "f 1/ 2/ 3/"}) {
    const ObjData obj = parseObjBytes(base + face + "\n");
    ASSERT_EQ(obj.mesh.faceCount(), 1u) << face;
    EXPECT_EQ(obj.mesh.faces[0], (Face{0, 1, 2})) << face;
    EXPECT_TRUE(obj.warnings.empty()) << face;
  }
}

TEST(ObjReader, PolygonIsFannedFromItsFirstCorner)
{
  // A regular hexagon of circumradius 3 in z = 2: four triangles around corner 1, area 3 sqrt(3) / 2 r^2.
  std::string text;
  for (int k = 0; k < 6; ++k)
    text += "v " + std::to_string(3.0 * std::cos(k * M_PI / 3)) + " " +
            std::to_string(3.0 * std::sin(k * M_PI / 3)) + " 2\n";
  const ObjData obj = parseObjBytes(text + "f 1 2 3 4 5 6\n");
  ASSERT_EQ(obj.mesh.faceCount(), 4u);
  for (int c = 1; c <= 4; ++c) EXPECT_EQ(obj.mesh.faces[static_cast<size_t>(c - 1)], (Face{0, c, c + 1}));
  EXPECT_NEAR(obj.mesh.area(), 1.5 * std::sqrt(3.0) * 9.0, 1e-5);  // std::to_string keeps 6 decimals
  for (size_t f = 0; f < 4; ++f) EXPECT_GT(obj.mesh.faceNormal(f).z(), 0.999);
  EXPECT_EQ(obj.polygonFaces, 1u);
}

TEST(ObjReader, ContinuationLinesCrlfTabsAndComments)
{
  const ObjData obj = parseObjBytes(
      "\xEF\xBB\xBF# made by hand\r\n"
      "v\t1 \\\r\n  2\t3   # the first vertex\r\n"
      "v 4 5 6\\\n\r\n"
      "\r\n   \t\n"
      "v 7 8 9 1.0\n"
      "f 1 \\\n2 \\\n 3\n");
  ASSERT_EQ(obj.mesh.vertexCount(), 3u);
  EXPECT_EQ(obj.mesh.vertices[0], Vec3(1, 2, 3));
  EXPECT_EQ(obj.mesh.vertices[1], Vec3(4, 5, 6));
  EXPECT_EQ(obj.mesh.vertices[2], Vec3(7, 8, 9));
  ASSERT_EQ(obj.mesh.faceCount(), 1u);
  EXPECT_EQ(obj.mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_TRUE(obj.warnings.empty());
}

TEST(ObjReader, WeightAndVertexColoursAfterXyzAreIgnored)
{
  const ObjData obj = parseObjBytes("v 1 2 3 1\nv -4 +5 6e1 0.5 0.25 0.125\nv 0.5 .5 5. 1 0 0 1\nf 1 2 3\n");
  ASSERT_EQ(obj.mesh.vertexCount(), 3u);
  EXPECT_EQ(obj.mesh.vertices[0], Vec3(1, 2, 3));
  EXPECT_EQ(obj.mesh.vertices[1], Vec3(-4, 5, 60));
  EXPECT_EQ(obj.mesh.vertices[2], Vec3(0.5, 0.5, 5));
}

TEST(ObjReader, WriterRoundTripKeepsEveryDoubleBit)
{
  TriangleMesh m = makeOpenCone(30.0, 20.0, 40.0, 16, 3);
  for (Vec3& p : m.vertices) p += Vec3(0.1, 1.0 / 3.0, -1e-9);
  const ObjData obj = parseObjBytes(encodeMesh(m, MeshFileFormat::Obj));
  ASSERT_EQ(obj.mesh.vertexCount(), m.vertexCount());
  for (size_t v = 0; v < m.vertexCount(); ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(obj.mesh.vertices[v][k], m.vertices[v][k]) << v;
  EXPECT_EQ(obj.mesh.faces, m.faces);
  EXPECT_TRUE(obj.warnings.empty());
}

TEST(ObjReader, StatementsWithoutGeometryAreReadPastQuietly)
{
  const ObjData obj = parseObjBytes(
      "mtllib part.mtl\no part\ng wall skin\ns 1\ns off\nusemtl steel\n"
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nvn 0 0 1\nvp 0.2 0.3\n"
      "l 1 2 3\np 1\nf 1 2 3\n");
  EXPECT_EQ(obj.mesh.faceCount(), 1u);
  EXPECT_EQ(obj.unknownStatements, 0u);
  EXPECT_TRUE(obj.warnings.empty());
}

TEST(ObjReader, UnknownStatementsGiveOneWarningNamingTheFirst)
{
  const ObjData obj =
      parseObjBytes("v 0 0 0\nv 1 0 0\nv 0 1 0\ncstype bspline\ndeg 3\nf 1 2 3\ncurv 0 1 1 2 3\nend\n");
  EXPECT_EQ(obj.mesh.faceCount(), 1u);
  EXPECT_EQ(obj.unknownStatements, 4u);
  ASSERT_EQ(obj.warnings.size(), 1u);
  EXPECT_EQ(obj.warnings[0],
            "'test.obj': 4 statements of a kind Spira does not read ignored, the first 'cstype' on line 4; "
            "Spira reads vertices ('v') and faces ('f')");
}

TEST(ObjReader, FacesWithFewerThanThreeCornersAreDroppedAndCounted)
{
  const ObjData obj = parseObjBytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nf\nf 1\nf 1 2\nf 1 2 3\n");
  ASSERT_EQ(obj.mesh.faceCount(), 1u);
  EXPECT_EQ(obj.degenerateFaces, 3u);
  ASSERT_EQ(obj.warnings.size(), 1u);
  EXPECT_EQ(obj.warnings[0], "3 faces in 'test.obj' with fewer than three corners ignored");
}

TEST(ObjReader, ProgressFollowsTheBytesAndCancelStops)
{
  // 70,000 triangles over 210,000 vertices: more statements than one progress stride.
  std::string text;
  for (int t = 0; t < 70000; ++t) text += "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n";
  std::vector<double> fractions;
  CallbackProgress progress([&](double f, std::string_view stage) {
    EXPECT_EQ(stage, "Reading OBJ");
    fractions.push_back(f);
  });
  const ObjData obj = parseObj(text, "big.obj", progress);
  EXPECT_EQ(obj.mesh.faceCount(), 70000u);
  ASSERT_GE(fractions.size(), 4u);  // 280,000 statements, one report per 65,536
  for (size_t i = 1; i < fractions.size(); ++i) EXPECT_GT(fractions[i], fractions[i - 1]);
  EXPECT_GE(fractions.front(), 0.0);
  EXPECT_LT(fractions.back(), 1.0);

  CallbackProgress cancelled;
  cancelled.cancel();
  EXPECT_THROW(parseObj(text, "big.obj", cancelled), Cancelled);
}

}  // namespace
}  // namespace spira::test
