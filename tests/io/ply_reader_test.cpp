// Spira's PLY reader on well-formed files of every encoding and layout exporters write.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "io_test_util.h"
#include "ply_bytes.h"
#include "spira/io/mesh_writers.h"
#include "spira/io/ply_reader.h"
#include "spira/mesh/mesh_primitives.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

TriangleMesh quarterThirds(TriangleMesh m)
{
  // Coordinates no float holds, so that the ASCII path must keep every digit.
  for (Vec3& p : m.vertices) p += Vec3(0.1, 1.0 / 3.0, -1e-9);
  return m;
}

TEST(PlyReader, AsciiRoundTripKeepsEveryDoubleBit)
{
  const TriangleMesh m = quarterThirds(makeOpenCylinder(20.0, 30.0, 24, 6));
  const PlyData ply = parsePlyBytes(encodeMesh(m, MeshFileFormat::PlyAscii));
  EXPECT_EQ(ply.encoding, PlyEncoding::Ascii);
  ASSERT_EQ(ply.mesh.vertexCount(), m.vertexCount());
  for (size_t v = 0; v < m.vertexCount(); ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(ply.mesh.vertices[v][k], m.vertices[v][k]) << v;
  EXPECT_EQ(ply.mesh.faces, m.faces);
  EXPECT_TRUE(ply.warnings.empty());
}

TEST(PlyReader, BinaryRoundTripKeepsEveryFloatBit)
{
  const TriangleMesh m = quarterThirds(makeOpenCone(30.0, 20.0, 40.0, 16, 3));
  const PlyData ply = parsePlyBytes(encodeMesh(m, MeshFileFormat::PlyBinary));
  EXPECT_EQ(ply.encoding, PlyEncoding::BinaryLittleEndian);
  ASSERT_EQ(ply.mesh.vertexCount(), m.vertexCount());
  for (size_t v = 0; v < m.vertexCount(); ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(ply.mesh.vertices[v][k], static_cast<double>(static_cast<float>(m.vertices[v][k]))) << v;
  EXPECT_EQ(ply.mesh.faces, m.faces);
  EXPECT_TRUE(ply.warnings.empty());
}

TEST(PlyReader, BigEndianReadsTheSameMeshAsLittleEndian)
{
  const TriangleMesh m = makeTetrahedron(7.5);
  for (bool big : {false, true}) {
    PlyBytes b(big);
    b.header(
        "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 4\nproperty list uchar int vertex_indices\n");
    for (const Vec3& p : m.vertices)
      for (int k = 0; k < 3; ++k) b.put(static_cast<float>(p[k]));
    for (const Face& f : m.faces) {
      b.put(std::uint8_t{3});
      for (int v : f) b.put(static_cast<std::int32_t>(v));
    }
    const PlyData ply = parsePlyBytes(b.bytes);
    EXPECT_EQ(ply.encoding, big ? PlyEncoding::BinaryBigEndian : PlyEncoding::BinaryLittleEndian);
    EXPECT_EQ(ply.mesh.faces, m.faces);
    EXPECT_LT(maxCornerDistance(ply.mesh, m), 1e-6) << big;
  }
}

TEST(PlyReader, CoordinatesOfEveryNumericTypeAndAlias)
{
  // x as double, y as a signed 16-bit integer, z as an unsigned byte, with a normal between them.
  for (bool big : {false, true}) {
    PlyBytes b(big);
    b.header(
        "element vertex 3\nproperty float64 x\nproperty float32 nx\nproperty int16 y\n"
        "property uint8 z\nelement face 1\nproperty list uint8 uint32 vertex_indices\n");
    const double xs[3] = {-1.25, 1e300, 0.1};
    const std::int16_t ys[3] = {-32768, 0, 32767};
    const std::uint8_t zs[3] = {0, 200, 255};
    for (int v = 0; v < 3; ++v) {
      b.put(xs[v]);
      b.put(0.5f);
      b.put(ys[v]);
      b.put(zs[v]);
    }
    b.put(std::uint8_t{3});
    for (std::uint32_t v : {2u, 1u, 0u}) b.put(v);
    const PlyData ply = parsePlyBytes(b.bytes);
    ASSERT_EQ(ply.mesh.vertexCount(), 3u);
    for (size_t v = 0; v < 3; ++v)
      EXPECT_EQ(ply.mesh.vertices[v], Vec3(xs[v], ys[v], zs[v])) << big << " vertex " << v;
    ASSERT_EQ(ply.mesh.faceCount(), 1u);
    EXPECT_EQ(ply.mesh.faces[0], (Face{2, 1, 0}));
  }
}

TEST(PlyReader, AsciiCoordinatesDeclaredAsIntegersAndCharAliases)
{
  const PlyData ply = parsePlyBytes(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty char x\nproperty short y\nproperty uint z\n"
      "element face 1\nproperty list char short vertex_indices\nend_header\n"
      "-128 -32768 4294967295\n+1 2 3\n0 0 0\n3 0 1 2\n");
  ASSERT_EQ(ply.mesh.vertexCount(), 3u);
  EXPECT_EQ(ply.mesh.vertices[0], Vec3(-128, -32768, 4294967295.0));
  EXPECT_EQ(ply.mesh.vertices[1], Vec3(1, 2, 3));
}

TEST(PlyReader, QuadMeshIsFanTriangulatedInFileOrder)
{
  // A 2 x 1 grid of quads in the z = 5 plane, plus a pentagon.
  const PlyData ply = parsePlyBytes(
      "ply\nformat ascii 1.0\ncomment two quads and a pentagon\nobj_info made by hand\n"
      "element vertex 8\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 3\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 5\n10 0 5\n20 0 5\n0 10 5\n10 10 5\n20 10 5\n10 20 5\n0 20 5\n"
      "4 0 1 4 3\n4 1 2 5 4\n5 3 4 5 6 7\n");
  EXPECT_EQ(ply.polygonFaces, 3u);
  ASSERT_EQ(ply.mesh.faceCount(), 2u + 2u + 3u);
  EXPECT_EQ(ply.mesh.faces[0], (Face{0, 1, 4}));
  EXPECT_EQ(ply.mesh.faces[1], (Face{0, 4, 3}));
  EXPECT_EQ(ply.mesh.faces[2], (Face{1, 2, 5}));
  EXPECT_EQ(ply.mesh.faces[6], (Face{3, 6, 7}));
  // Two 10 x 10 quads and a convex pentagon of area 150 (shoelace).
  EXPECT_NEAR(ply.mesh.area(), 200.0 + 150.0, 1e-9);
  ASSERT_EQ(ply.warnings.size(), 1u);
  EXPECT_NE(ply.warnings[0].find("3 faces in 'test.ply' with more than three corners split into triangles"),
            std::string::npos)
      << ply.warnings[0];
}

// Normals, colours, a vertex list property, a face colour and texture list before the corners,
// and two elements Spira does not use (one with a list): all read past, in both encodings.
std::string extrasHeader()
{
  return std::string(
      "element vertex 3\nproperty float nx\nproperty float ny\nproperty float nz\n"
      "property float x\nproperty uchar red\nproperty float y\nproperty list uchar float tags\n"
      "property float z\nproperty uchar alpha\n"
      "element edge 2\nproperty int vertex1\nproperty int vertex2\nproperty list ushort short path\n"
      "element face 2\nproperty uchar flags\nproperty list uchar float texcoord\n"
      "property list int uint vertex_index\nproperty ushort material\n"
      "element material 1\nproperty double shininess\n");
}

void expectExtrasMesh(const PlyData& ply)
{
  ASSERT_EQ(ply.mesh.vertexCount(), 3u);
  EXPECT_EQ(ply.mesh.vertices[0], Vec3(1, 2, 3));
  EXPECT_EQ(ply.mesh.vertices[1], Vec3(4, 5, 6));
  EXPECT_EQ(ply.mesh.vertices[2], Vec3(7, 8, 9));
  ASSERT_EQ(ply.mesh.faceCount(), 2u);
  EXPECT_EQ(ply.mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(ply.mesh.faces[1], (Face{2, 1, 0}));
  ASSERT_EQ(ply.warnings.size(), 2u);
  EXPECT_NE(ply.warnings[0].find("element 'edge' (2 'edge' items) was ignored"), std::string::npos)
      << ply.warnings[0];
  EXPECT_NE(ply.warnings[1].find("element 'material' (1 'material' item) was ignored"), std::string::npos)
      << ply.warnings[1];
}

TEST(PlyReader, AsciiExtraPropertiesAndElementsAreSkipped)
{
  const PlyData ply = parsePlyBytes("ply\nformat ascii 1.0\n" + extrasHeader() +
                                    "end_header\n"
                                    "0 0 1 1 255 2 0 3 7\n0 0 1 4 0 5 2 -1.5 2.5 6 7\n0 0 1 7 9 8 1 3 9 0\n"
                                    "\n"  // blank lines between items are tolerated
                                    "0 1 3 -7 8 9\n1 2 0\n"
                                    "9 4 0.5 0.5 0.5 0.5 3 0 1 2 1\n0 0 3 2 1 0 2\n0.25\n");
  expectExtrasMesh(ply);
}

TEST(PlyReader, BinaryExtraPropertiesAndElementsAreSkipped)
{
  for (bool big : {false, true}) {
    PlyBytes b(big);
    b.header(extrasHeader());
    for (int v = 0; v < 3; ++v) {
      b.put(0.f), b.put(0.f), b.put(1.f);
      b.put(static_cast<float>(3 * v + 1));
      b.put(std::uint8_t{255});
      b.put(static_cast<float>(3 * v + 2));
      b.put(static_cast<std::uint8_t>(v));  // tags: v floats
      for (int t = 0; t < v; ++t) b.put(2.5f);
      b.put(static_cast<float>(3 * v + 3));
      b.put(std::uint8_t{7});
    }
    for (int e = 0; e < 2; ++e) {
      b.put(std::int32_t{0}), b.put(std::int32_t{1});
      b.put(std::uint16_t{2}), b.put(std::int16_t{-7}), b.put(std::int16_t{8});
    }
    const int corners[2][3] = {{0, 1, 2}, {2, 1, 0}};
    for (const auto& face : corners) {
      b.put(std::uint8_t{9});
      b.put(std::uint8_t{2}), b.put(0.5f), b.put(0.5f);
      b.put(std::int32_t{3});
      for (int v : face) b.put(static_cast<std::uint32_t>(v));
      b.put(std::uint16_t{1});
    }
    b.put(0.25);
    SCOPED_TRACE(big);
    expectExtrasMesh(parsePlyBytes(b.bytes));
  }
}

TEST(PlyReader, WindowsLineEndingsAndBlankHeaderLines)
{
  const PlyData ply = parsePlyBytes(
      "ply\r\nformat ascii 1.0\r\n\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\n"
      "property float z\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
      "0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n");
  ASSERT_EQ(ply.mesh.faceCount(), 1u);
  EXPECT_EQ(ply.mesh.vertices[1], Vec3(1, 0, 0));
  EXPECT_TRUE(ply.warnings.empty());
}

TEST(PlyReader, BinaryAfterCrLfEndHeader)
{
  PlyBytes b(false, "\r\n");
  b.header(
      "element vertex 3\r\nproperty float x\r\nproperty float y\r\n"
      "property float z\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\n");
  // A first coordinate whose first byte is '\n' must not be taken for part of the header's line end.
  for (float c : {1.4e-44f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) b.put(c);
  b.put(std::uint8_t{3});
  for (std::int32_t v : {0, 1, 2}) b.put(v);
  const PlyData ply = parsePlyBytes(b.bytes);
  ASSERT_EQ(ply.mesh.faceCount(), 1u);
  EXPECT_EQ(ply.mesh.vertices[0].x(), static_cast<double>(1.4e-44f));
  EXPECT_EQ(ply.mesh.vertices[2], Vec3(0, 1, 0));
}

TEST(PlyReader, AsciiNonFiniteValuesAreReadForTheImportToReport)
{
  const PlyData ply = parsePlyBytes(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "nan 0 0\n1e999 0 0\n-1e999 1e-999 0\n3 0 1 2\n");
  EXPECT_TRUE(std::isnan(ply.mesh.vertices[0].x()));
  EXPECT_EQ(ply.mesh.vertices[1].x(), std::numeric_limits<double>::infinity());
  EXPECT_EQ(ply.mesh.vertices[2].x(), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(ply.mesh.vertices[2].y(), 0.0);
}

TEST(PlyReader, ReadsAFileFromDisk)
{
  TempDir dir;
  const TriangleMesh m = makeOpenCylinder(5.0, 8.0, 12, 2);
  writeMesh(m, dir / "c.ply");
  NullProgress progress;
  const PlyData ply = readPly(dir / "c.ply", progress);
  EXPECT_EQ(ply.mesh.faces, m.faces);
  EXPECT_LT(maxCornerDistance(ply.mesh, m), 1e-5);
}

}  // namespace
}  // namespace spira::test
