// Writers and importers checked against each other: a mesh written in every format and read
// back through importPart must come back as the same welded mesh.
#include <gtest/gtest.h>

#include <cstring>

#include "io_test_util.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

struct FormatCase {
  MeshFileFormat format;
  const char* fileName;
  const char* importerId;
};

class RoundTrip : public ::testing::TestWithParam<FormatCase> {};

// Float formats store 24-bit mantissas: 2^-24 relative to a coordinate of ~100 mm is ~6e-6 mm.
constexpr double kFloatTolerance = 2e-5;

void expectSameReport(const MeshReport& a, const MeshReport& b)
{
  EXPECT_EQ(a.vertexCount, b.vertexCount);
  EXPECT_EQ(a.faceCount, b.faceCount);
  EXPECT_EQ(a.edgeCount, b.edgeCount);
  EXPECT_EQ(a.partClass, b.partClass);
  EXPECT_EQ(a.boundaryLoops.size(), b.boundaryLoops.size());
  EXPECT_EQ(a.componentCount, b.componentCount);
  EXPECT_EQ(a.issues.size(), b.issues.size());
  EXPECT_NEAR(a.area, b.area, 1e-6 * a.area);
}

TEST_P(RoundTrip, OpenCylinderComesBackIdentical)
{
  const FormatCase c = GetParam();
  const TriangleMesh original = makeOpenCylinder(60.0, 90.0, 48, 12);
  TempDir dir;
  writeMesh(original, dir / c.fileName, c.format);
  const ImportedPart part = importFile(dir / c.fileName);

  EXPECT_EQ(part.importerId, c.importerId);
  EXPECT_EQ(part.sourceUnit, LengthUnit::Millimetre);
  ASSERT_EQ(part.mesh.vertexCount(), original.vertexCount());
  ASSERT_EQ(part.mesh.faceCount(), original.faceCount());
  EXPECT_TRUE(sameConnectivity(part.mesh, original));
  EXPECT_LT(maxCornerDistance(part.mesh, original), kFloatTolerance);
  EXPECT_EQ(part.weld.outputVertices, original.vertexCount());
  expectSameReport(part.report, validateMesh(original));
  EXPECT_EQ(part.report.partClass, PartClass::Open);
  EXPECT_GE(part.seconds.read, 0.0);
  EXPECT_GE(part.seconds.total(), part.seconds.read);
}

TEST_P(RoundTrip, ClosedTetrahedronKeepsOrientation)
{
  const FormatCase c = GetParam();
  const TriangleMesh original = makeTetrahedron(25.0);
  TempDir dir;
  writeMesh(original, dir / c.fileName, c.format);
  const ImportedPart part = importFile(dir / c.fileName);
  ASSERT_EQ(part.mesh.faceCount(), 4u);
  EXPECT_EQ(part.mesh.vertexCount(), 4u);
  EXPECT_TRUE(part.report.boundaryLoops.empty());  // watertight
  EXPECT_FALSE(part.report.hasIssue(MeshIssueKind::InconsistentOrientation));
  EXPECT_NEAR(signedVolume(part.mesh), signedVolume(original), 1e-4);
  EXPECT_GT(signedVolume(part.mesh), 0.0);
}

INSTANTIATE_TEST_SUITE_P(AllFormats, RoundTrip,
                         ::testing::Values(FormatCase{MeshFileFormat::StlBinary, "part.stl", "import.stl"},
                                           FormatCase{MeshFileFormat::StlAscii, "part.stl", "import.stl"},
                                           FormatCase{MeshFileFormat::Obj, "part.obj", "import.obj"},
                                           FormatCase{MeshFileFormat::PlyAscii, "part.ply", "import.ply"},
                                           FormatCase{MeshFileFormat::PlyBinary, "part.ply", "import.ply"}),
                         [](const ::testing::TestParamInfo<FormatCase>& param) {
                           switch (param.param.format) {
                             case MeshFileFormat::StlBinary:
                               return std::string("StlBinary");
                             case MeshFileFormat::StlAscii:
                               return std::string("StlAscii");
                             case MeshFileFormat::Obj:
                               return std::string("Obj");
                             case MeshFileFormat::PlyAscii:
                               return std::string("PlyAscii");
                             case MeshFileFormat::PlyBinary:
                               return std::string("PlyBinary");
                           }
                           return std::string("Unknown");
                         });

TEST(RoundTripExact, AsciiFormatsKeepDoublesExactly)
{
  // Coordinates that no float can hold: the ASCII writers must not round them.
  TriangleMesh m = makeTetrahedron(10.0);
  for (Vec3& p : m.vertices) p += Vec3(0.1, 1.0 / 3.0, 1e-9);
  TempDir dir;
  writeMesh(m, dir / "t.stl", MeshFileFormat::StlAscii);
  const ImportedPart stl = importFile(dir / "t.stl");
  EXPECT_EQ(maxCornerDistance(stl.mesh, m), 0.0);
}

TEST(ForeignFiles, ObjPolygonsAndPlyExtrasAreRead)
{
  TempDir dir;
  // Two quads sharing an edge, with normals and texture coordinates as exporters write them.
  writeBytes(dir / "quads.obj",
             "# two quads\nv 0 0 0\nv 10 0 0\nv 20 0 0\nv 0 10 0\nv 10 10 0\nv 20 10 0\nvn 0 0 1\nvt 0 0\n"
             "f 1/1/1 2/1/1 5/1/1 4/1/1\nf 2/1/1 3/1/1 6/1/1 5/1/1\n");
  const ImportedPart obj = importFile(dir / "quads.obj");
  EXPECT_EQ(obj.mesh.faceCount(), 4u);
  EXPECT_EQ(obj.mesh.vertexCount(), 6u);
  EXPECT_NEAR(obj.mesh.area(), 200.0, 1e-9);
  EXPECT_GT(obj.mesh.faceNormal(0).z(), 0.99);  // counter-clockwise seen from +Z stays so
  EXPECT_EQ(obj.report.boundaryLoops.size(), 1u);

  // A PLY with extra vertex properties and a quad face.
  writeBytes(dir / "quad.ply",
             "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
             "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\n"
             "property list uchar uint vertex_index\nend_header\n"
             "0 0 0 255 0 0\n4 0 0 0 255 0\n4 3 0 0 0 255\n0 3 0 9 9 9\n4 0 1 2 3\n");
  const ImportedPart ply = importFile(dir / "quad.ply");
  EXPECT_EQ(ply.mesh.faceCount(), 2u);
  EXPECT_EQ(ply.mesh.vertexCount(), 4u);
  EXPECT_NEAR(ply.mesh.area(), 12.0, 1e-9);
}

TEST(MeshWriters, BinaryStlLayout)
{
  const TriangleMesh m = makeOpenCone(30.0, 20.0, 40.0, 16, 3);
  const std::string bytes = encodeMesh(m, MeshFileFormat::StlBinary, "cone");
  ASSERT_EQ(bytes.size(), 84 + 50 * m.faceCount());
  EXPECT_NE(bytes.substr(0, 5), "solid");  // would mislead readers that sniff the header
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  EXPECT_EQ(count, m.faceCount());
  // The stored normal of face 0 is the unit normal of its corners.
  float n[3];
  std::memcpy(n, bytes.data() + 84, sizeof n);
  const Vec3 expected = m.faceNormal(0);
  EXPECT_NEAR(n[0], expected.x(), 1e-6);
  EXPECT_NEAR(n[1], expected.y(), 1e-6);
  EXPECT_NEAR(n[2], expected.z(), 1e-6);
}

TEST(MeshWriters, TextFormatsCountElements)
{
  const TriangleMesh m = makeHemisphere(40.0, 24, 8);
  const auto count = [](const std::string& s, const std::string& prefix) {
    size_t n = 0;
    for (size_t pos = 0; (pos = s.find("\n" + prefix, pos)) != std::string::npos; ++pos) ++n;
    return n;
  };
  const std::string obj = encodeMesh(m, MeshFileFormat::Obj);
  EXPECT_EQ(count(obj, "v "), m.vertexCount());
  EXPECT_EQ(count(obj, "f "), m.faceCount());
  const std::string stl = encodeMesh(m, MeshFileFormat::StlAscii);
  EXPECT_EQ(count(stl, "facet normal"), m.faceCount());
  EXPECT_EQ(count(stl, "  vertex"), 3 * m.faceCount());
  const std::string ply = encodeMesh(m, MeshFileFormat::PlyBinary);
  EXPECT_NE(ply.find("element vertex " + std::to_string(m.vertexCount()) + "\n"), std::string::npos);
  const size_t header = ply.find("end_header\n") + 11;
  EXPECT_EQ(ply.size(), header + 12 * m.vertexCount() + 13 * m.faceCount());
}

TEST(MeshWriters, ExtensionPicksFormatAndUnknownIsRefused)
{
  EXPECT_EQ(meshFileFormatForPath("a/B.STL"), MeshFileFormat::StlBinary);
  EXPECT_EQ(meshFileFormatForPath("x.obj"), MeshFileFormat::Obj);
  EXPECT_EQ(meshFileFormatForPath("x.Ply"), MeshFileFormat::PlyBinary);
  EXPECT_FALSE(meshFileFormatForPath("x.step"));
  TempDir dir;
  const TriangleMesh m = makeTetrahedron(5.0);
  EXPECT_TRUE(throwsOneLine<InputError>([&] { writeMesh(m, dir / "x.3mf"); }, "x.3mf"));
  EXPECT_TRUE(throwsOneLine<IoError>([&] { writeMesh(m, dir / "missing" / "x.stl"); }));
  writeMesh(m, dir / "x.stl");
  EXPECT_EQ(std::filesystem::file_size(dir / "x.stl"), 84u + 50u * 4u);
}

}  // namespace
}  // namespace spira::test
