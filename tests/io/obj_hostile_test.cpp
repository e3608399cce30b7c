// Hostile OBJ files (tests/data/hostile/obj, and huge ones made here) end in a one-line refusal that
// names the file and the line, never a crash, a hang, a large allocation or a library's own words.
// Each file runs through the import service, so these tests judge whichever reader is registered
// for .obj.
#include <gtest/gtest.h>

#include <utility>

#include "io_test_util.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

std::filesystem::path hostile(const std::string& name)
{
  return sourceDir() / "tests" / "data" / "hostile" / "obj" / name;
}

TEST(ObjHostile, EveryStoredFileIsRefusedNamingTheLine)
{
  // What Assimp did with each is in tests/data/hostile/obj/README.md; faces_before_vertices.obj it
  // imported without a word.
  const std::pair<const char*, const char*> cases[] = {
      {"truncated.obj", "'truncated.obj' line 6: the vertex has 2 coordinates; 'v' needs x, y and z"},
      {"binary_garbage.obj",
       "'binary_garbage.obj' line 1: the file holds binary data (a byte 0x05), not OBJ text"},
      {"index_zero.obj",
       "'index_zero.obj' line 4: the face corner '0' names vertex 0, but OBJ numbers vertices from 1"},
      {"index_beyond_count.obj",
       "'index_beyond_count.obj' line 5: the face corner '9' names vertex 9, but only 4 vertices are defined "
       "above it"},
      {"huge_negative_index.obj",
       "'huge_negative_index.obj' line 4: the face corner '-9223372036854775808' names vertex "
       "-9223372036854775808, "
       "but only 3 vertices"},
      {"faces_before_vertices.obj",
       "'faces_before_vertices.obj' line 1: the face corner '1' names vertex 1, but no vertex is defined "
       "above it"},
      {"huge_exponent.obj",
       "'huge_exponent.obj' line 2: the coordinate '1e400' is beyond the range of a double"},
      {"nan.obj", "'nan.obj' line 2: the coordinate 'nan' is not a finite number"},
      {"empty.obj", "'empty.obj' is empty (0 bytes)"},
  };
  for (const auto& [name, message] : cases) EXPECT_TRUE(refusedImport(hostile(name), message)) << name;
}

TEST(ObjHostile, FiveMegabyteTokensAreRefusedWithoutEchoingThem)
{
  // Assimp read the 5 MB coordinate as a small number and imported the part, and ran for minutes on
  // the 5 MB corner.
  const std::string digits(5'000'000, '1');
  const std::string clipped = std::string(40, '1') + "...'";
  TempDir dir;
  writeBytes(dir / "coordinate.obj", "v 1 0 0\nv 0 1 0\nv 0 0 " + digits + "\nf 1 2 3\n");
  writeBytes(dir / "corner.obj", "v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 " + digits + "\n");
  writeBytes(dir / "keyword.obj", std::string(5'000'000, 'k') + "\n");
  EXPECT_TRUE(refusedImport(dir / "coordinate.obj", "'coordinate.obj' line 3: the coordinate '" + clipped +
                                                        " is beyond the range of a double"));
  EXPECT_TRUE(refusedImport(dir / "corner.obj", "'corner.obj' line 4: the vertex index of the face corner '" +
                                                    clipped +
                                                    " is beyond the range of a 64-bit whole number"));
  EXPECT_TRUE(refusedImport(dir / "keyword.obj", "'keyword.obj' has no faces ('f' lines) and no vertices"));
  for (const char* name : {"coordinate.obj", "corner.obj", "keyword.obj"}) try {
      importFile(dir / name);
    } catch (const InputError& e) {
      EXPECT_LT(std::string(e.what()).size() + e.hint().size(), 400u) << name;
    }
}

TEST(ObjHostile, MillionVerticesWithoutFacesAreNoSurface)
{
  std::string text;
  for (int v = 0; v < 1'000'000; ++v) text += "v 0 0 0\n";
  TempDir dir;
  writeBytes(dir / "cloud.obj", text);
  EXPECT_TRUE(refusedImport(dir / "cloud.obj",
                            "'cloud.obj' has no faces ('f' lines): it holds 1000000 vertices only"));
}

}  // namespace
}  // namespace spira::test
