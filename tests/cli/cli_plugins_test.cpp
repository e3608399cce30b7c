#include <gtest/gtest.h>

#include <set>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

TEST(CliPlugins, JsonListsEverySchemaField)
{
  const CliRun r = runCli({"plugins", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::set<std::string> ids;
  for (const auto& p : j) {
    ids.insert(p["id"].get<std::string>());
    for (const auto& param : p["parameters"])
      for (const char* field :
           {"key", "type", "default", "min", "max", "unit", "label", "tooltip", "category"})
        EXPECT_TRUE(param.contains(field)) << p["id"] << " " << param.dump() << " lacks " << field;
  }
  for (const char* id :
       {"import.stl", "import.obj", "import.ply", "import.step", "import.iges", "import.brep"})
    EXPECT_EQ(ids.count(id), 1u) << id;
}

TEST(CliPlugins, InfoHelpShowsGeneratedFlagsWithUnits)
{
  const CliRun r = runCli({"info", "--help"});
  ASSERT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("--linear-deflection X[mm]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--angular-deflection X[deg]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--unit mm|cm|m|in"), std::string::npos) << r.out;
}

TEST(CliSample, BundledSamplesAreWhatTheGeneratorMakes)
{
  TempDir dir;
  for (const auto& [name, file] : std::vector<std::pair<std::string, std::string>>{
           {"open-cylinder", "open_cylinder.stl"}, {"dome", "dome.stl"}, {"cone", "cone.stl"}}) {
    const auto out = dir / file;
    const CliRun r = runCli({"sample", name, "-o", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto bundled = sourceDir() / "resources" / "samples" / file;
    const std::string made = readBytes(out);
    const std::string kept = readBytes(bundled);
    EXPECT_EQ(made.size(), kept.size()) << file;
    EXPECT_TRUE(made == kept) << file
                              << " differs from the generator's output: regenerate it with spira-cli sample";
  }
}

TEST(CliSample, UnwritableOutputFailsCleanly)
{
  TempDir dir;
  const auto target = dir / "no" / "such" / "dir" / "x.stl";
  const CliRun r = runCli({"sample", "dome", "-o", target.string()});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_FALSE(std::filesystem::exists(target));
  EXPECT_EQ(runCli({"sample", "teapot", "-o", (dir / "t.stl").string()}).exitCode, 3);
}

}  // namespace
}  // namespace spira::test
