#include <gtest/gtest.h>

#include "spira/base/error.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/plugin/strategy_name.h"

namespace spira {
namespace {

class FakeImporter : public ImporterPlugin {
 public:
  explicit FakeImporter(std::string id, std::vector<std::string> exts)
      : id_(std::move(id)), exts_(std::move(exts))
  {
  }
  std::string id() const override { return id_; }
  std::string label() const override { return "Fake"; }
  std::string description() const override { return "Fake importer"; }
  const ParamSchema& schema() const override { return schema_; }
  std::vector<std::string> extensions() const override { return exts_; }
  ImportedMesh read(const std::filesystem::path&, const ParamSet&, Progress&) const override { return {}; }

 private:
  std::string id_;
  std::vector<std::string> exts_;
  ParamSchema schema_;
};

TEST(PluginRegistry, RejectsDuplicateAndMalformedIds)
{
  PluginRegistry r;
  r.add(std::make_unique<FakeImporter>("import.fake", std::vector<std::string>{"fak"}));
  EXPECT_THROW(r.add(std::make_unique<FakeImporter>("import.fake", std::vector<std::string>{"x"})),
               InternalError);
  EXPECT_THROW(r.add(std::make_unique<FakeImporter>("Import.Fake2", std::vector<std::string>{"x"})),
               InternalError);
  EXPECT_THROW(r.add(std::make_unique<FakeImporter>("nodot", std::vector<std::string>{"x"})), InternalError);
  EXPECT_EQ(r.all().size(), 1u);
}

TEST(PluginRegistry, FindsImporterByExtensionCaseInsensitive)
{
  PluginRegistry r;
  r.add(std::make_unique<FakeImporter>("import.a", std::vector<std::string>{"stl"}));
  r.add(std::make_unique<FakeImporter>("import.b", std::vector<std::string>{"step", "stp"}));
  EXPECT_EQ(r.importerForFile("/x/y/Part.STL").id(), "import.a");
  EXPECT_EQ(r.importerForFile("a.b/part.stp").id(), "import.b");
  try {
    r.importerForFile("part.dwg");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(".dwg"), std::string::npos);
    EXPECT_NE(e.hint().find(".step, .stl, .stp"), std::string::npos);
  }
  EXPECT_THROW(r.importerForFile("noextension"), InputError);
  EXPECT_THROW(r.importerForFile("dir.stl/file"), InputError);
}

TEST(PluginRegistry, TypedLookupListsAlternatives)
{
  PluginRegistry r;
  r.add(std::make_unique<FakeImporter>("import.a", std::vector<std::string>{"stl"}));
  EXPECT_EQ(r.importer("import.a").id(), "import.a");
  try {
    r.decomposer("import.a");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown decomposer 'import.a'"), std::string::npos);
  }
}

TEST(PluginId, Validation)
{
  EXPECT_TRUE(isValidPluginId("export.fanuc_tp"));
  EXPECT_TRUE(isValidPluginId("closure.max_min_geodesic"));
  EXPECT_FALSE(isValidPluginId("export"));
  EXPECT_FALSE(isValidPluginId("export.Fanuc"));
  EXPECT_FALSE(isValidPluginId(".x"));
  EXPECT_FALSE(isValidPluginId("a..b"));
}

TEST(StrategyName, OneNameWrittenBothAccepted)
{
  EXPECT_EQ(strategyName("decomposer.isovalue"), "isovalue");
  EXPECT_EQ(strategyName("isovalue"), "isovalue");
  EXPECT_EQ(strategyName("planar_2.5d"), "planar_2.5d");
  EXPECT_EQ(decomposerIdOf("geodesic"), "decomposer.geodesic");
  EXPECT_EQ(decomposerIdOf("decomposer.geodesic"), "decomposer.geodesic");
  EXPECT_EQ(decomposerIdOf(strategyName("decomposer.envelope_projection")), "decomposer.envelope_projection");
}

}  // namespace
}  // namespace spira
