// Every way a PLY header or body can be malformed ends in one InputError naming the place.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "io_test_util.h"
#include "ply_bytes.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira::test {
namespace {

const std::string kXyz = "property float x\nproperty float y\nproperty float z\n";
const std::string kFaces = "element face 1\nproperty list uchar int vertex_indices\n";

::testing::AssertionResult refuses(const std::string& bytes, const std::string& mustContain)
{
  return throwsOneLine<InputError>([&] { parsePlyBytes(bytes); }, mustContain);
}

std::string asciiFile(const std::string& body)
{
  return "ply\nformat ascii 1.0\nelement vertex 3\n" + kXyz + kFaces + "end_header\n" + body;
}

TEST(PlyReaderErrors, HeaderGrammar)
{
  EXPECT_TRUE(refuses("solid x\n", "'test.ply' is not a PLY file: it does not start with the line 'ply'"));
  EXPECT_TRUE(refuses("plywood\n", "does not start with the line 'ply'"));
  EXPECT_TRUE(refuses("ply", "no 'end_header' line before the file ends (line 1)"));
  EXPECT_TRUE(refuses("ply\nformat binary_middle_endian 1.0\nend_header\n",
                      "line 2: the PLY header has the format 'binary_middle_endian'"));
  EXPECT_TRUE(refuses("ply\nformat ascii 2.0\nend_header\n", "line 2: the PLY header has PLY version '2.0'"));
  EXPECT_TRUE(refuses("ply\nformat ascii\nend_header\n", "not 'format <encoding> 1.0'"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nformat ascii 1.0\nend_header\n",
                      "line 3: the PLY header has a second 'format'"));
  EXPECT_TRUE(
      refuses("ply\nelement vertex 3\nend_header\n", "line 2: the PLY header has an 'element' line before"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nproperty float x\nend_header\n",
                      "line 3: the PLY header has a 'property' line before any 'element'"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nelement vertex -3\nend_header\n",
                      "the count '-3' of element 'vertex'"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nelement vertex 18446744073709551616\nend_header\n",
                      "which is not a whole number of at most 2^64 - 1"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nelement vertex 1\nelement vertex 1\nend_header\n",
                      "line 4: the PLY header has a second element named 'vertex'"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
                      "line 4: the PLY header has the type 'float128'"));
  EXPECT_TRUE(
      refuses("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty double x\nend_header\n",
              "a second property 'x' in element 'vertex'"));
  EXPECT_TRUE(
      refuses("ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n",
              "a list whose count type is 'float'"));
  EXPECT_TRUE(
      refuses("ply\nformat ascii 1.0\nelement face 1\nproperty list uchar vertex_indices\nend_header\n",
              "not 'property list <count type> <item type> <name>'"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nvertices 3\nend_header\n",
                      "'vertices', which is not a PLY header keyword"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nend_header\n", "has no 'vertex' element"));
}

TEST(PlyReaderErrors, ElementsSpiraNeeds)
{
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nelement vertex 1\n" + kXyz + "end_header\n0 0 0\n",
                      "has no 'face' element in its PLY header: it holds points only"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n" +
                          kFaces + "end_header\n",
                      "line 3: element 'vertex' has no scalar property 'z'"));
  EXPECT_TRUE(
      refuses("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
              "property list uchar float z\n" +
                  kFaces + "end_header\n",
              "has no scalar property 'z'"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nelement vertex 1\n" + kXyz +
                          "element face 1\nproperty list uchar int corners\nend_header\n",
                      "line 7: element 'face' has no list property 'vertex_indices' (or 'vertex_index')"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nelement vertex 1\n" + kXyz +
                          "element face 1\nproperty int vertex_indices\nend_header\n",
                      "has no list property 'vertex_indices'"));
  EXPECT_TRUE(refuses("ply\nformat ascii 1.0\nelement vertex 1\n" + kXyz +
                          "element face 1\nproperty list uchar float vertex_indices\nend_header\n",
                      "the corner indices of element 'face' do not have an integer type"));
}

TEST(PlyReaderErrors, AsciiItemsThatDoNotMatchTheHeader)
{
  EXPECT_TRUE(
      refuses(asciiFile("0 0 0\n1 0\n0 1 0\n3 0 1 2\n"),
              "'test.ply' line 11: vertex 1 has fewer values than the header declares for element 'vertex'"));
  EXPECT_TRUE(refuses(
      asciiFile("0 0 0\n1 0 0 1\n0 1 0\n3 0 1 2\n"),
      "line 11: vertex 1 has more values than the header declares for element 'vertex' (from '1' on)"));
  EXPECT_TRUE(refuses(asciiFile("0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n"), "line 13: face 0 has fewer values"));
  EXPECT_TRUE(
      refuses(asciiFile("0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n"), "line 13: face 0 has more values"));
  EXPECT_TRUE(refuses(asciiFile("0 0 0\n1 0x10 0\n0 1 0\n3 0 1 2\n"),
                      "line 11: expected a number in vertex 1, found '0x10'"));
  EXPECT_TRUE(refuses(asciiFile("0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n"),
                      "line 13: expected a whole number in face 0, found '1.5'"));
  EXPECT_TRUE(refuses(asciiFile("0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n"),
                      "line 13: face 0 has a list 'vertex_indices' of -3 values"));
  EXPECT_TRUE(refuses(asciiFile("0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n"), "line 13: face 0 refers to vertex -1"));
  EXPECT_TRUE(refuses(asciiFile("0 0 0\n1 0 0\n0 1 0\n"),
                      "declares 3 vertices, 1 face, which take at least 19 bytes, but only 18 bytes follow"));
  EXPECT_TRUE(refuses(asciiFile("0 0 0\n1 0 0\n0 1 0\n3 0 1"), "'test.ply' ends after 0 of the 1 face"));
}

TEST(PlyReaderErrors, AsciiTextAfterTheLastElementIsAWarning)
{
  const PlyData ply = parsePlyBytes(asciiFile("0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n  \nextra stuff\n"));
  ASSERT_EQ(ply.mesh.faceCount(), 1u);
  ASSERT_EQ(ply.warnings.size(), 1u);
  EXPECT_EQ(ply.warnings[0], "'test.ply' line 16: the text after the last element was ignored");
}

TEST(PlyReaderErrors, BinaryListsThatRunPastTheEnd)
{
  for (bool big : {false, true}) {
    PlyBytes b(big);
    b.header("element vertex 3\n" + kXyz + "element face 1\nproperty list int int vertex_indices\n");
    for (int i = 0; i < 9; ++i) b.put(0.f);
    const size_t countAt = b.bytes.size();
    std::string negative = b.bytes, huge = b.bytes;
    b.put(std::int32_t{-2});
    negative = b.bytes;
    b.bytes.resize(countAt);
    b.put(std::int32_t{2000000000});
    for (std::int32_t v : {0, 1, 2}) b.put(v);
    huge = b.bytes;
    EXPECT_TRUE(refuses(negative, "byte " + std::to_string(countAt + 4) +
                                      ": face 0 has a list 'vertex_indices' of -2 values"));
    EXPECT_TRUE(refuses(huge, "'test.ply' ends after 0 of the 1 face its PLY header declares"));
  }
}

TEST(PlyReaderErrors, ElementWithoutPropertiesTakesNoTimeWhateverItsCount)
{
  // 2^64 - 1 items of nothing: nothing to read, so nothing to loop over.
  const PlyData ply = parsePlyBytes(
      "ply\nformat binary_little_endian 1.0\nelement nothing 18446744073709551615\n"
      "element vertex 0\n" +
      kXyz + "element face 0\nproperty list uchar int vertex_indices\nend_header\n");
  EXPECT_EQ(ply.mesh.faceCount(), 0u);
}

// Random damage to valid files, as a fuzzer makes it: every result is a mesh or an InputError.
TEST(PlyReaderErrors, DamagedFilesAreReadOrRefusedNeverAnythingElse)
{
  const TriangleMesh m = makeOpenCylinder(10.0, 10.0, 8, 3);
  std::mt19937 rng(15);
  size_t read = 0, refused = 0;
  for (MeshFileFormat format : {MeshFileFormat::PlyAscii, MeshFileFormat::PlyBinary}) {
    const std::string valid = encodeMesh(m, format);
    for (int trial = 0; trial < 400; ++trial) {
      std::string bytes = valid;
      const auto at = [&] { return static_cast<size_t>(rng() % bytes.size()); };
      switch (trial % 4) {
        case 0:
          bytes.resize(at());
          break;
        case 1:
          for (int k = 0; k < 3; ++k) bytes[at()] = static_cast<char>(rng() & 0xFF);
          break;
        case 2:
          bytes.insert(at(), 1, static_cast<char>(rng() & 0xFF));
          break;
        default:
          bytes.erase(at(), 1 + rng() % 8);
          break;
      }
      try {
        parsePlyBytes(bytes);
        ++read;
      } catch (const InputError& e) {
        ++refused;
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      }
    }
  }
  // Both outcomes occur: the damage reaches the header, the counts and the values.
  EXPECT_GT(read, 50u);
  EXPECT_GT(refused, 200u);
}

}  // namespace
}  // namespace spira::test
