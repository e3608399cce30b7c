#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "io_test_util.h"
#include "spira/base/error.h"
#include "spira/io/mesh_writers.h"
#include "spira/io/stl_reader.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira::test {
namespace {

StlData parse(const std::string& bytes)
{
  NullProgress progress;
  return parseStl(bytes, "test.stl", progress);
}

TEST(StlReader, BinaryIsASoupInFileOrder)
{
  const TriangleMesh m = makeOpenCylinder(10.0, 5.0, 8, 2);
  const StlData stl = parse(encodeMesh(m, MeshFileFormat::StlBinary));
  EXPECT_TRUE(stl.binary);
  ASSERT_EQ(stl.soup.faceCount(), m.faceCount());
  ASSERT_EQ(stl.soup.vertexCount(), 3 * m.faceCount());
  for (size_t f = 0; f < m.faceCount(); ++f) {
    const int b = static_cast<int>(3 * f);
    EXPECT_EQ(stl.soup.faces[f], (Face{b, b + 1, b + 2}));
  }
  EXPECT_LT(maxCornerDistance(stl.soup, m), 1e-5);
}

TEST(StlReader, BinaryWhoseHeaderStartsWithSolidIsBinary)
{
  const TriangleMesh m = makeTetrahedron(3.0);
  std::string bytes = encodeMesh(m, MeshFileFormat::StlBinary);
  const std::string header = "solid exported by a CAD program that writes ASCII-looking headers";
  std::memcpy(bytes.data(), header.data(), header.size());
  const StlData stl = parse(bytes);
  EXPECT_TRUE(stl.binary);
  EXPECT_EQ(stl.soup.faceCount(), 4u);
  EXPECT_LT(maxCornerDistance(stl.soup, m), 1e-6);
}

TEST(StlReader, AsciiToleratesCaseBlankLinesPolygonsAndSeveralSolids)
{
  const std::string text =
      "  SOLID first part\r\n"
      "FACET NORMAL 0 0 1\r\n  OUTER LOOP\r\n    VERTEX 0 0 0\r\n    VERTEX +1.5 0 0\r\n    VERTEX 0 1e0 "
      "0\r\n"
      "  ENDLOOP\r\nENDFACET\r\n\r\n"
      "ENDSOLID first part\r\n"
      "solid second\n"
      "facet normal 0 0 0\n outer loop\n vertex 0 0 1\n vertex 2 0 1\n vertex 2 2 1\n vertex 0 2 1\n "
      "endloop\n"
      "endfacet\n"
      "endsolid second\n";
  const StlData stl = parse(text);
  EXPECT_FALSE(stl.binary);
  EXPECT_EQ(stl.name, "first part");
  EXPECT_EQ(stl.polygonFacets, 1u);
  ASSERT_EQ(stl.soup.faceCount(), 3u);  // one triangle + a quad split in two
  EXPECT_EQ(stl.soup.vertices[1], Vec3(1.5, 0, 0));
  EXPECT_EQ(stl.soup.vertices[2], Vec3(0, 1, 0));
  EXPECT_EQ(stl.soup.vertices[8], Vec3(0, 2, 1));
}

TEST(StlReader, AsciiNanIsReadForTheImportToReport)
{
  const StlData stl = parse(
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\nvertex 0 1 "
      "0\nendloop\nendfacet\n"
      "endsolid s\n");
  ASSERT_EQ(stl.soup.vertexCount(), 3u);
  EXPECT_TRUE(std::isnan(stl.soup.vertices[1].x()));
}

TEST(StlReader, AsciiOverflowBecomesInfinity)
{
  const StlData stl = parse(
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 1e999 0 0\nvertex 1 1e-999 0\nvertex 0 1 0\nendloop\n"
      "endfacet\nendsolid s\n");
  EXPECT_TRUE(std::isinf(stl.soup.vertices[0].x()));
  EXPECT_EQ(stl.soup.vertices[1].y(), 0.0);
}

TEST(StlReader, MalformedAsciiNamesTheLine)
{
  const std::string text =
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 zero 0\nvertex 0 1 "
      "0\nendloop\nendfacet\n";
  EXPECT_TRUE(throwsOneLine<InputError>([&] { parse(text); }, "line 5: expected a number, found 'zero'"));
  EXPECT_TRUE(throwsOneLine<InputError>(
      [&] {
        parse("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n");
      },
      "a facet has 2 vertices"));
  EXPECT_TRUE(throwsOneLine<InputError>([&] { parse("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0"); },
                                        "the end of the file"));
}

TEST(StlReader, WrongTriangleCountGivesBothSizes)
{
  std::string bytes = encodeMesh(makeTetrahedron(2.0), MeshFileFormat::StlBinary);
  bytes.resize(bytes.size() - 7);  // truncated: 84 + 200 - 7 = 277 bytes
  EXPECT_TRUE(throwsOneLine<InputError>([&] { parse(bytes); }, "take 284 bytes, but the file has 277 bytes"));
  try {
    parse(bytes);
  } catch (const InputError& e) {
    EXPECT_EQ(e.hint(), "the file is truncated or not an STL");
  }
  std::string tooMany = encodeMesh(makeTetrahedron(2.0), MeshFileFormat::StlBinary);
  const std::uint32_t lie = 1000;
  std::memcpy(tooMany.data() + 80, &lie, 4);
  EXPECT_TRUE(throwsOneLine<InputError>([&] { parse(tooMany); }, "announces 1000 triangles"));
}

TEST(StlReader, EmptyAndTinyFilesAreRefused)
{
  EXPECT_TRUE(throwsOneLine<InputError>([&] { parse(""); }, "is empty"));
  EXPECT_TRUE(throwsOneLine<InputError>([&] { parse(std::string(40, '\x01')); }, "too short"));
}

TEST(StlReader, CancelStopsTheRead)
{
  const std::string bytes = encodeMesh(makeOpenCylinder(10.0, 5.0, 64, 8), MeshFileFormat::StlBinary);
  CallbackProgress progress;
  progress.cancel();
  EXPECT_THROW(parseStl(bytes, "x.stl", progress), Cancelled);
}

}  // namespace
}  // namespace spira::test
