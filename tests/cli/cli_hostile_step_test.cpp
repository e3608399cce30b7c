// Damaged STEP files through the real spira-cli: bad input (exit 3) with the file named on one
// line of stderr, and nothing of OpenCASCADE's on stdout, where `info --json` writes its JSON.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

fs::path hostile(const std::string& name)
{
  return sourceDir() / "tests/data/hostile/step" / name;
}

void expectRefused(const CliRun& r, const std::string& name, const std::string& cause)
{
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(r.out.empty()) << "stdout: " << r.out;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
  EXPECT_NE(r.err.find("'" + name + "'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(cause), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("re-export"), std::string::npos) << "no hint: " << r.err;
}

TEST(CliHostileStep, InfoAndPlanRefuseDamagedFilesWithTheFileNamed)
{
  const std::vector<std::pair<std::string, std::string>> files = {
      {"wrong_type_crash.step", "the STEP reader crashed on"},
      {"wrong_type_reference.step", "declares 6 faces but only 5 could be read"},
      {"missing_reference.step", "declares 6 faces but only 5 could be read"},
      {"unresolved_face.step", "declares 6 faces but only 5 could be read"},
  };
  TempDir dir;
  for (const auto& [name, cause] : files) {
    SCOPED_TRACE(name);
    const std::string file = hostile(name).string();
    expectRefused(runCli({"info", file}), name, cause);
    expectRefused(runCli({"info", file, "--json"}), name, cause);
    expectRefused(runCli({"plan", file, "-o", (dir / name).string()}), name, cause);
    EXPECT_FALSE(fs::exists(dir / name / "trajectory.csv"));
  }
}

TEST(CliHostileStep, OpenCascadeMessagesAreWarningsNotStdout)
{
  const CliRun r = runCli({"info", hostile("unresolved_point.step").string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // throws, failing the test, on anything but JSON
  EXPECT_NEAR(j["area_mm2"].get<double>(), 2200.0, 1e-9);
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_NE(j["warnings"][0].get<std::string>().find("Unresolved Reference"), std::string::npos)
      << j["warnings"];
}

}  // namespace
}  // namespace spira::test
