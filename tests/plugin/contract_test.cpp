// Contract tests: every plugin registered in the built-in registry goes through the same
// checks, so a new plugin is tested the moment it is linked in.
#include <gtest/gtest.h>

#include <cctype>
#include <map>
#include <set>

#include "builtin_plugins.h"
#include "spira/base/error.h"
#include "spira/io/import_service.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/plugin/plugin_registry.h"
#include "support/test_support.h"

namespace spira {
namespace {

const std::map<PluginKind, std::string> kIdPrefix = {{PluginKind::Importer, "import."},
                                                     {PluginKind::Decomposer, "decomposer."},
                                                     {PluginKind::ClosureFinder, "closure."},
                                                     {PluginKind::Exporter, "export."}};

TEST(PluginContract, RegistryHoldsTheBuiltInImporters)
{
  const auto importers = builtinRegistry().ofKind(PluginKind::Importer);
  EXPECT_GE(importers.size(), 6u);
}

TEST(PluginContract, EveryPluginDeclaresItselfCompletely)
{
  for (const auto& p : builtinRegistry().all()) {
    SCOPED_TRACE(p->id());
    EXPECT_TRUE(isValidPluginId(p->id()));
    EXPECT_EQ(p->id().rfind(kIdPrefix.at(p->kind()), 0), 0u) << "id prefix does not match the plugin kind";
    EXPECT_FALSE(p->label().empty());
    EXPECT_GE(p->description().size(), 20u) << "description too short to help a user";
    const auto problems = p->schema().selfCheck();
    for (const auto& problem : problems) ADD_FAILURE() << problem;
    // The defaults validate and convert to internal units without throwing.
    const ParamSet defaults = p->schema().defaults();
    EXPECT_NO_THROW(p->schema().validate(defaults));
    for (const auto& d : p->schema().defs()) {
      if (d.type == ParamType::Double || d.type == ParamType::Int) {
        EXPECT_NO_THROW(defaults.internal(p->schema(), d.key));
      }
    }
  }
}

TEST(PluginContract, ImporterExtensionsAreLowercaseAndUnique)
{
  std::set<std::string> seen;
  for (const Plugin* p : builtinRegistry().ofKind(PluginKind::Importer)) {
    const auto& imp = static_cast<const ImporterPlugin&>(*p);
    EXPECT_FALSE(imp.extensions().empty()) << p->id();
    for (const auto& e : imp.extensions()) {
      EXPECT_TRUE(seen.insert(e).second) << "extension ." << e << " claimed twice";
      for (char c : e) {
        EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) ||
                    std::isdigit(static_cast<unsigned char>(c)));
      }
    }
  }
}

TEST(PluginContract, EveryImporterRejectsMissingEmptyAndGarbageFilesCleanly)
{
  test::TempDir dir;
  NullProgress progress;
  for (const Plugin* p : builtinRegistry().ofKind(PluginKind::Importer)) {
    const auto& imp = static_cast<const ImporterPlugin&>(*p);
    for (const auto& ext : imp.extensions()) {
      SCOPED_TRACE(p->id() + " ." + ext);
      EXPECT_THROW(importPart(builtinRegistry(), dir / ("missing." + ext), nullptr, progress), IoError);
      test::writeBytes(dir / ("empty." + ext), "");
      EXPECT_THROW(importPart(builtinRegistry(), dir / ("empty." + ext), nullptr, progress), InputError);
      test::writeBytes(dir / ("garbage." + ext),
                       std::string("\x01\x02 this is not a model \xff\xfe", 26) + std::string(300, '#'));
      EXPECT_THROW(importPart(builtinRegistry(), dir / ("garbage." + ext), nullptr, progress), InputError);
    }
  }
}

TEST(PluginContract, MeshImportersReadWhatSpiraWrites)
{
  test::TempDir dir;
  NullProgress progress;
  const TriangleMesh tetra = makeTetrahedron(10.0);
  int checked = 0;
  for (const Plugin* p : builtinRegistry().ofKind(PluginKind::Importer)) {
    for (const auto& ext : static_cast<const ImporterPlugin&>(*p).extensions()) {
      const auto file = dir / ("tetra." + ext);
      if (!meshFileFormatForPath(file)) continue;  // CAD formats are checked in tests/io
      SCOPED_TRACE(p->id());
      writeMesh(tetra, file);
      const ImportedPart part = importPart(builtinRegistry(), file, nullptr, progress);
      EXPECT_EQ(part.importerId, p->id());
      EXPECT_EQ(part.mesh.vertexCount(), 4u);
      EXPECT_EQ(part.mesh.faceCount(), 4u);
      EXPECT_NEAR(part.mesh.area(), tetra.area(), 1e-4 * tetra.area());
      EXPECT_EQ(part.report.boundaryLoops.size(), 0u);
      ++checked;
    }
  }
  EXPECT_GE(checked, 3);
}

}  // namespace
}  // namespace spira
