#include <gtest/gtest.h>

#include "io_test_util.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

struct UnitCase {
  const char* unit;
  LengthUnit expected;
  double factor;
};

class MeshUnits : public ::testing::TestWithParam<UnitCase> {};

TEST_P(MeshUnits, CoordinatesAreScaledToMillimetres)
{
  const UnitCase c = GetParam();
  const TriangleMesh original = makeOpenCone(0.05, 0.03, 0.08, 24, 4);  // a small part in file units
  TriangleMesh expected = original;
  for (Vec3& p : expected.vertices) p *= c.factor;
  TempDir dir;
  for (const char* name : {"p.stl", "p.obj", "p.ply"}) {
    writeMesh(original, dir / name);
    const ImportedPart part = importFile(dir / name, "unit", std::string(c.unit));
    EXPECT_EQ(part.sourceUnit, c.expected) << name;
    ASSERT_EQ(part.mesh.faceCount(), original.faceCount()) << name;
    EXPECT_EQ(part.mesh.vertexCount(), original.vertexCount()) << name;
    // Float files: relative error 2^-24 of the largest coordinate.
    EXPECT_LT(maxCornerDistance(part.mesh, expected), 1e-6 * c.factor) << name;
    EXPECT_NEAR(part.mesh.bounds().size().z(), 0.08 * c.factor, 1e-6 * c.factor) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(AllUnits, MeshUnits,
                         ::testing::Values(UnitCase{"mm", LengthUnit::Millimetre, 1.0},
                                           UnitCase{"cm", LengthUnit::Centimetre, 10.0},
                                           UnitCase{"m", LengthUnit::Metre, 1000.0},
                                           UnitCase{"in", LengthUnit::Inch, 25.4}),
                         [](const ::testing::TestParamInfo<UnitCase>& param) {
                           return std::string(param.param.unit);
                         });

TEST(MeshUnits, EveryMeshImporterDeclaresTheSameUnitParameter)
{
  for (const char* id : {"import.stl", "import.obj", "import.ply"}) {
    const ImporterPlugin& importer = ioRegistry().importer(id);
    EXPECT_TRUE(importer.schema().selfCheck().empty()) << id;
    const ParamDef* unit = importer.schema().find("unit");
    ASSERT_NE(unit, nullptr) << id;
    EXPECT_EQ(unit->type, ParamType::Choice);
    EXPECT_EQ(std::get<std::string>(unit->defaultValue), "mm");
    EXPECT_EQ(unit->choices, (std::vector<std::string>{"mm", "cm", "m", "in"}));
    EXPECT_EQ(unit->category, "Import");
    for (const std::string& choice : unit->choices) EXPECT_TRUE(parseLengthUnit(choice)) << choice;
  }
}

}  // namespace
}  // namespace spira::test
