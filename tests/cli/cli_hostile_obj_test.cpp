// spira-cli on hostile OBJ files: exit code 3 (bad input) and one line naming the file and the line
// at fault, never a crash, a hang or Assimp's words; the reader's warnings reach the user.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "cli_runner.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

TEST(CliHostileObj, EveryStoredFileExitsWith3NamingFileAndLine)
{
  const std::pair<const char*, const char*> cases[] = {
      {"truncated.obj", "line 6: the vertex has 2 coordinates"},
      {"binary_garbage.obj", "line 1: the file holds binary data"},
      {"index_zero.obj", "line 4: the face corner '0' names vertex 0"},
      {"index_beyond_count.obj", "line 5: the face corner '9' names vertex 9"},
      {"huge_exponent.obj", "line 2: the coordinate '1e400' is beyond the range of a double"},
      {"nan.obj", "line 2: the coordinate 'nan' is not a finite number"},
      {"huge_negative_index.obj", "line 4: the face corner '-9223372036854775808'"},
      {"faces_before_vertices.obj", "line 1: the face corner '1' names vertex 1, but no vertex"},
  };
  for (const auto& [name, what] : cases) {
    SCOPED_TRACE(name);
    const auto file = sourceDir() / "tests" / "data" / "hostile" / "obj" / name;
    const CliRun r = runCli({"info", file.string()});
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_EQ(r.err.rfind("spira-cli: '" + std::string(name) + "' " + what, 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

TEST(CliHostileObj, SplitPolygonsAndUnknownStatementsAreWarnings)
{
  TempDir dir;
  writeBytes(dir / "quad.obj", "v 0 0 0\nv 80 0 0\nv 80 0 60\nv 0 0 60\nbevel on\nf 1 2 3 4\n");
  const CliRun r = runCli({"info", (dir / "quad.obj").string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("warning: 1 face in 'quad.obj' with more than three corners split into triangles"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("warning: 'quad.obj': 1 statement of a kind Spira does not read ignored, the first "
                       "'bevel' on line 5"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace spira::test
