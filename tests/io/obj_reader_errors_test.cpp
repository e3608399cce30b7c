// Every way an OBJ can be malformed ends in one InputError naming the line and the text at fault.
#include <gtest/gtest.h>

#include "io_test_util.h"
#include "obj_bytes.h"

namespace spira::test {
namespace {

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

::testing::AssertionResult refuses(const std::string& bytes, const std::string& mustContain)
{
  return throwsOneLine<InputError>([&] { parseObjBytes(bytes); }, mustContain);
}

TEST(ObjReaderErrors, CoordinatesThatAreNotFiniteNumbers)
{
  EXPECT_TRUE(refuses(kTriangle + "v 1 abc 3\n", "'test.obj' line 4: the coordinate 'abc' is not a number"));
  EXPECT_TRUE(refuses("v 1,5 0 0\n", "line 1: the coordinate '1,5' is not a number"));
  EXPECT_TRUE(refuses("v 0x10 0 0\n", "line 1: the coordinate '0x10' is not a number"));
  EXPECT_TRUE(refuses("\n\nv 0 1e400 0\n",
                      "line 3: the coordinate '1e400' is beyond the range of a double (about 1.8e308)"));
  EXPECT_TRUE(refuses("v 0 0 -1e400\n", "the coordinate '-1e400' is beyond the range of a double"));
  EXPECT_TRUE(refuses("v nan 0 0\n", "line 1: the coordinate 'nan' is not a finite number"));
  EXPECT_TRUE(refuses("v 0 -inf 0\n", "line 1: the coordinate '-inf' is not a finite number"));
  EXPECT_TRUE(refuses("v 0 0 infinity\n", "the coordinate 'infinity' is not a finite number"));
}

TEST(ObjReaderErrors, VertexWithFewerThanThreeCoordinates)
{
  EXPECT_TRUE(
      refuses(kTriangle + "v 1 2\nf 1 2 3\n", "line 4: the vertex has 2 coordinates; 'v' needs x, y and z"));
  EXPECT_TRUE(refuses("v 1 # y and z are missing\n", "line 1: the vertex has 1 coordinate; 'v' needs"));
  EXPECT_TRUE(refuses("v\n", "line 1: the vertex has 0 coordinates"));
}

TEST(ObjReaderErrors, CornersThatNameNoVertex)
{
  EXPECT_TRUE(
      refuses(kTriangle + "f 0 1 2\n",
              "'test.obj' line 4: the face corner '0' names vertex 0, but OBJ numbers vertices from 1"));
  EXPECT_TRUE(refuses(kTriangle + "f 1 2 4\n",
                      "line 4: the face corner '4' names vertex 4, but only 3 vertices are defined above it "
                      "(1 to 3, or -1 to -3)"));
  EXPECT_TRUE(refuses(kTriangle + "f -1 -2 -4/1/1\n",
                      "line 4: the face corner '-4/1/1' names vertex -4, but only 3"));
  EXPECT_TRUE(refuses(
      "v 0 0 0\nf 1 -1 2\n",
      "line 2: the face corner '2' names vertex 2, but only 1 vertex is defined above it (1, or -1)"));
  EXPECT_TRUE(refuses("f 1 2 3\n" + kTriangle,
                      "line 1: the face corner '1' names vertex 1, but no vertex is defined above it"));
  // Beyond 64 bits either way, and the one 64-bit value whose negation overflows.
  EXPECT_TRUE(
      refuses(kTriangle + "f 1 2 99999999999999999999\n",
              "line 4: the vertex index of the face corner '99999999999999999999' is beyond the range of "
              "a 64-bit whole number"));
  EXPECT_TRUE(
      refuses(kTriangle + "f 1 2 -99999999999999999999\n", "is beyond the range of a 64-bit whole number"));
  EXPECT_TRUE(
      refuses(kTriangle + "f 1 2 -9223372036854775808\n", "names vertex -9223372036854775808, but only 3"));
}

TEST(ObjReaderErrors, CornersThatAreNotOfTheFourForms)
{
  EXPECT_TRUE(refuses(kTriangle + "f 1 2 x\n",
                      "line 4: the vertex index of the face corner 'x' is not a whole number"));
  EXPECT_TRUE(refuses(kTriangle + "f 1 2 2.5\n", "the face corner '2.5' is not a whole number"));
  EXPECT_TRUE(refuses(kTriangle + "f 1 2 /3\n", "the face corner '/3' is not a whole number"));
  EXPECT_TRUE(refuses(kTriangle + "f 1 2 3/1/1/1\n",
                      "line 4: the face corner '3/1/1/1' is not v, v/vt, v//vn or v/vt/vn"));
  EXPECT_TRUE(refuses(kTriangle + "f 1 2 3/a\n", "the face corner '3/a' is not v, v/vt, v//vn or v/vt/vn"));
  EXPECT_TRUE(refuses(kTriangle + "f 1 2 3//n\n", "the face corner '3//n' is not v, v/vt, v//vn or v/vt/vn"));
}

TEST(ObjReaderErrors, LineNumbersCountPhysicalLinesThroughContinuationsAndCrlf)
{
  EXPECT_TRUE(refuses("# header\r\nv 0 \\\r\n 0 \\\n 0\r\n\r\nv 1 0 oops\r\n",
                      "'test.obj' line 6: the coordinate 'oops'"));
  EXPECT_TRUE(refuses(kTriangle + "f 1 \\\n 2 \\\n 7\n", "line 6: the face corner '7'"));
}

TEST(ObjReaderErrors, BinaryDataIsNotText)
{
  EXPECT_TRUE(refuses(std::string("v 0 0 0\n\x01\x02\x03 1 2\n", 16),
                      "'test.obj' line 2: the file holds binary data (a byte 0x01), not OBJ text"));
  EXPECT_TRUE(refuses(std::string("\0\0\0\0", 4), "line 1: the file holds binary data (a byte 0x00)"));
}

TEST(ObjReaderErrors, FilesWithoutASurface)
{
  EXPECT_TRUE(refuses("", "'test.obj' is empty (0 bytes)"));
  EXPECT_TRUE(refuses(" \n\t\r\n# only a comment\n", "'test.obj' has no faces ('f' lines) and no vertices"));
  EXPECT_TRUE(
      refuses(kTriangle + "l 1 2 3\np 1\n", "'test.obj' has no faces ('f' lines): it holds 3 vertices only"));
  EXPECT_TRUE(refuses(kTriangle + "f 1 2\nf\n",
                      "'test.obj' has no face with three or more corners (only 2 with fewer)"));
}

TEST(ObjReaderErrors, LongTokensAreClippedInTheMessage)
{
  const std::string token(100000, '7');
  try {
    parseObjBytes(kTriangle + "v 0 0 " + token + "\n");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("line 4: the coordinate '" + std::string(40, '7') + "...' is beyond the range"),
              std::string::npos)
        << what;
    EXPECT_LT(what.size(), 200u);
  }
}

}  // namespace
}  // namespace spira::test
