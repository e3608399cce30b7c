// spira-cli on hostile PLY files: exit code 3 (bad input) and one message naming the file, never a
// crash, a hang or a library's own words.
#include <gtest/gtest.h>

#include <string>

#include "cli_runner.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

constexpr int kBadInput = 3;

TEST(CliHostilePly, EveryRefusedFileExitsWith3AndNamesIt)
{
  for (const char* name : {"cut_in_format.ply", "no_end_header.ply", "huge_vertex_count.ply",
                           "index_out_of_range.ply", "truncated_faces.ply"}) {
    SCOPED_TRACE(name);
    const auto file = sourceDir() / "tests" / "data" / "hostile" / "ply" / name;
    const CliRun r = runCli({"info", file.string()});
    EXPECT_EQ(r.exitCode, kBadInput) << r.err;
    EXPECT_EQ(r.err.rfind("spira-cli: '" + std::string(name) + "'", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find("aiMesh"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

TEST(CliHostilePly, FaceWithoutCornersIsReadWithAWarning)
{
  const auto file = sourceDir() / "tests" / "data" / "hostile" / "ply" / "empty_face.ply";
  const CliRun r = runCli({"info", file.string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("warning: 1 face in 'empty_face.ply' with fewer than three corners ignored"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace spira::test
