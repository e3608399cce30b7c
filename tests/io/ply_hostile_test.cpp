// Hostile PLY files (tests/data/hostile/ply, and variants made here) end in a one-line refusal that
// names the file and the place, or in an import with a warning; never a crash, a hang, a large
// allocation or a library's own message. Each file runs through the import service, so these tests
// judge whichever reader is registered for .ply.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "io_test_util.h"
#include "ply_bytes.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

std::filesystem::path hostile(const std::string& name)
{
  return sourceDir() / "tests" / "data" / "hostile" / "ply" / name;
}

TEST(PlyHostile, FaceWithoutCornersIsDroppedWithAWarning)
{
  // Assimp aborted on this one (an assertion in its triangulation).
  const ImportedPart part = importFile(hostile("empty_face.ply"));
  ASSERT_EQ(part.mesh.faceCount(), 1u);
  EXPECT_NEAR(part.mesh.area(), 0.5, 1e-12);
  EXPECT_TRUE(hasImportWarning(part, "1 face in 'empty_face.ply' with fewer than three corners ignored"));
}

TEST(PlyHostile, OnlyFacesWithoutCornersIsNoSurface)
{
  TempDir dir;
  writeBytes(
      dir / "corners.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0\n2 0 1\n");
  EXPECT_TRUE(refusedImport(dir / "corners.ply", "contains no triangles"));
}

TEST(PlyHostile, CornerIndexOutOfRangeNamesFaceLineAndVertexCount)
{
  EXPECT_TRUE(refusedImport(hostile("index_out_of_range.ply"),
                            "'index_out_of_range.ply' line 14: face 0 refers to vertex 9, but the file has 4 "
                            "vertices (indices 0 to 3)"));
}

TEST(PlyHostile, NegativeAndOutOfRangeBinaryIndicesNameTheByte)
{
  const TriangleMesh m = makeTetrahedron(2.0);
  for (std::int32_t bad : {-1, 4, 2147483647}) {
    std::string bytes = encodeMesh(m, MeshFileFormat::PlyBinary);
    const size_t body = bytes.find("end_header\n") + 11;
    // Face 2's second corner: after 4 vertices of 12 bytes and two faces of 13 bytes, its count byte
    // and first corner.
    const size_t at = body + 4 * 12 + 2 * 13 + 1 + 4;
    std::memcpy(bytes.data() + at, &bad, 4);
    TempDir dir;
    writeBytes(dir / "bad.ply", bytes);
    EXPECT_TRUE(refusedImport(dir / "bad.ply", "'bad.ply' byte " + std::to_string(at + 4) +
                                                   ": face 2 refers to vertex " + std::to_string(bad)))
        << bad;
  }
}

TEST(PlyHostile, HeaderCutInsideTheFormatLine)
{
  EXPECT_TRUE(
      refusedImport(hostile("cut_in_format.ply"), "no 'end_header' line before the file ends (line 2)"));
}

TEST(PlyHostile, HeaderWithoutEndHeaderBeforeTheData)
{
  EXPECT_TRUE(
      refusedImport(hostile("no_end_header.ply"),
                    "'no_end_header.ply' line 9: the PLY header has '0', which is not a PLY header keyword "
                    "(the 'end_header' line is missing before the data)"));
}

TEST(PlyHostile, HeaderThatNeverEndsIsRefusedAfter64KiB)
{
  // Comment lines only, 1 MiB of them: the search for end_header stops at the header limit.
  std::string bytes = "ply\nformat binary_little_endian 1.0\n";
  while (bytes.size() < (size_t{1} << 20)) bytes += "comment no end in sight\n";
  TempDir dir;
  writeBytes(dir / "endless.ply", bytes);
  EXPECT_TRUE(refusedImport(dir / "endless.ply", "no 'end_header' line in its first 65536 bytes"));
}

TEST(PlyHostile, DeclaredCountsBeyondTheFileSizeAreRefusedBeforeAllocating)
{
  // 167 bytes declaring 99,999,999 vertices: Assimp allocated 3.5 GB and read for minutes.
  EXPECT_TRUE(
      refusedImport(hostile("huge_vertex_count.ply"),
                    "'huge_vertex_count.ply': the PLY header declares 99999999 vertices, 1 face, which take "
                    "at least 599999995 bytes, but only 6 bytes follow the header"));
}

TEST(PlyHostile, BinaryCountsBeyondTheFileSizeAndBeyond64Bits)
{
  TempDir dir;
  for (const char* count : {"99999999", "18446744073709551615"}) {
    PlyBytes b(false);
    b.header(std::string("element vertex 3\nproperty double x\n"
                         "property double y\nproperty double z\nelement face ") +
             count + "\nproperty list uchar int vertex_indices\n");
    for (int i = 0; i < 9; ++i) b.put(0.0);
    writeBytes(dir / "count.ply", b.bytes);
    EXPECT_TRUE(refusedImport(dir / "count.ply",
                              std::string("3 vertices, ") + count + " faces, which take at least"));
  }
}

TEST(PlyHostile, AsciiTruncatedAfterHalfItsFacesIsRefused)
{
  EXPECT_TRUE(refusedImport(hostile("truncated_faces.ply"),
                            "'truncated_faces.ply' ends after 1 of the 2 faces its PLY header declares"));
}

TEST(PlyHostile, BinaryTruncatedAfterHalfItsFacesIsRefused)
{
  const TriangleMesh m = makeOpenCylinder(10.0, 10.0, 16, 4);
  const std::string bytes = encodeMesh(m, MeshFileFormat::PlyBinary);
  const size_t body = bytes.find("end_header\n") + 11;
  const size_t faces = m.faceCount();
  const size_t cut = body + 12 * m.vertexCount() + 13 * (faces / 2) + 7;  // inside the next face
  TempDir dir;
  writeBytes(dir / "half.ply", bytes.substr(0, cut));
  EXPECT_TRUE(refusedImport(dir / "half.ply", "'half.ply' ends after " + std::to_string(faces / 2) +
                                                  " of the " + std::to_string(faces) +
                                                  " faces its PLY header declares"));
}

TEST(PlyHostile, TrailingBytesAreImportedWithAWarning)
{
  const TriangleMesh m = makeTetrahedron(2.0);
  std::string bytes = encodeMesh(m, MeshFileFormat::PlyBinary);
  const size_t end = bytes.size();
  bytes += "garbage";
  TempDir dir;
  writeBytes(dir / "tail.ply", bytes);
  const ImportedPart part = importFile(dir / "tail.ply");
  EXPECT_EQ(part.mesh.faceCount(), 4u);
  EXPECT_TRUE(hasImportWarning(
      part, "'tail.ply' byte " + std::to_string(end) + ": the 7 bytes after the last element were ignored"));
}

TEST(PlyHostile, NonFiniteCoordinatesAreRefusedByTheImport)
{
  TempDir dir;
  writeBytes(dir / "nan.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 nan 0\n0 1 0\n"
             "3 0 1 2\n");
  EXPECT_TRUE(refusedImport(dir / "nan.ply", "1 vertices have non-finite coordinates"));
}

}  // namespace
}  // namespace spira::test
