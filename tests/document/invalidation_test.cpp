#include <functional>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "document/document_test_data.h"
#include "spira/base/transform.h"
#include "spira/document/document.h"
#include "spira/document/invalidation.h"

namespace spira {
namespace {

// Stages up to (not including) `s`.
constexpr StageMask before(Stage s)
{
  return kAllStages & ~stagesFrom(s);
}

struct Case {
  const char* what;
  std::function<void(Document&)> edit;
  StageMask kept;  // stages whose result survives the edit
};

TEST(Invalidation, EachSettingKindDropsExactlyItsStages)
{
  const std::vector<Case> cases = {
      {"new mesh",
       [](Document& d) {
         Part p = *d.part();
         p.mesh = std::make_shared<const TriangleMesh>(test::tetrahedron(3.0));
         d.setPart(p);
       },
       before(Stage::Field)},
      {"source unit",
       [](Document& d) {
         Part p = *d.part();
         p.sourceUnit = LengthUnit::Millimetre;
         d.setPart(p);
       },
       before(Stage::Field)},
      {"remove part", [](Document& d) { d.clearPart(); }, before(Stage::Field)},
      {"lower boundary", [](Document& d) { d.setLowerBoundaryOverride(0); }, before(Stage::Field)},
      // Moved, or turned about the world's vertical: the part is built along the same direction.
      {"placement",
       [](Document& d) {
         Transform T = d.part()->T_world_part;
         T.translation() += Vec3(0, 0, 9);
         d.setPartPlacement(T);
       },
       before(Stage::Kinematics)},
      {"turn about the vertical",
       [](Document& d) {
         d.setPartPlacement(Transform(Eigen::AngleAxisd(0.5, Vec3::UnitZ())) * d.part()->T_world_part);
       },
       before(Stage::Kinematics)},
      // A tilt changes the build direction in the part frame: the plan starts over.
      {"tilt",
       [](Document& d) {
         d.setPartPlacement(Transform(Eigen::AngleAxisd(0.3, Vec3::UnitX())) * d.part()->T_world_part);
       },
       before(Stage::Field)},
      {"part name",
       [](Document& d) {
         Part p = *d.part();
         p.name = "renamed";
         d.setPart(p, "Rename part");
       },
       before(Stage::Export)},
      {"substrate", [](Document& d) { d.setSubstrate(Substrate::plane(1.0)); }, before(Stage::Field)},
      {"decomposer id", [](Document& d) { d.setDecomposer("decomposer.isovalue"); },
       before(Stage::Generatrices)},
      {"active decomposer params", [](Document& d) { d.setParam("decomposer.geodesic", "smoothing", 2.0); },
       before(Stage::Generatrices)},
      {"inactive decomposer params", [](Document& d) { d.setParam("decomposer.isovalue", "levels", 3.0); },
       kAllStages},
      {"closure finder id", [](Document& d) { d.setClosureFinder("closure.max_min_geodesic"); },
       before(Stage::Generatrices)},
      {"active closure params", [](Document& d) { d.setParam("closure.zone", "radius", 2.0); },
       before(Stage::Generatrices)},
      {"inactive closure params", [](Document& d) { d.setParam("closure.max_min_geodesic", "radius", 2.0); },
       kAllStages},
      {"spiral params", [](Document& d) { d.setParam("spiral", "points_per_mm", 2.0); },
       before(Stage::Spiral)},
      {"process params", [](Document& d) { d.setParam("process", "travel_speed", 1.0); },
       before(Stage::Process)},
      {"process section removed",
       [](Document& d) {
         PlanSettings s = *d.settings();
         s.params.erase("process");
         d.setPlanSettings(s);
       },
       before(Stage::Process)},
      {"thermal switched on", [](Document& d) { d.setParam("thermal", "enabled", true); },
       before(Stage::Thermal)},
      {"thermal params while on",
       [](Document& d) {
         Document::Transaction t(d, "Thermal limit");
         d.setParam("thermal", "enabled", true);
         d.setParam("thermal", "interpass_max", 250.0);
         t.commit();
       },
       before(Stage::Thermal)},
      // Off, the stage's values feed nothing: the plan keeps everything.
      {"thermal params while off", [](Document& d) { d.setParam("thermal", "interpass_max", 250.0); },
       kAllStages},
      {"cell", [](Document& d) { d.setCell(CellRecord()); }, before(Stage::Kinematics)},
      {"cell removed", [](Document& d) { d.clearCell(); }, before(Stage::Kinematics)},
      // A scan measures the part; no stage is planned from it.
      {"scan compared",
       [](Document& d) {
         d.setScan(ScanRecord{"wall.ply", Transform::Identity(), 0.02, 10});
       },
       kAllStages},
      {"exporter params", [](Document& d) { d.setParam("export.krl", "base", std::int64_t{1}); },
       before(Stage::Export)},
      {"importer params", [](Document& d) { d.setParam("import.stl", "unit", std::string("in")); },
       kAllStages},
      {"unknown section", [](Document& d) { d.setParam("mystery", "x", true); }, 0},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    Document doc(test::fullState());
    ASSERT_EQ(doc.results().presentStages(), kAllStages);
    const DocumentState old = doc.snapshot();
    c.edit(doc);
    ASSERT_NE(doc.state(), old);
    EXPECT_EQ(doc.results().presentStages(), c.kept);
    for (int i = 0; i < kStageCount; ++i) {
      const bool kept = (c.kept & stageBit(stageAt(i))) != 0;
      // Every stage but export has a report.
      EXPECT_EQ(doc.results().reports.has(stageAt(i)), kept && stageAt(i) != Stage::Export)
          << stageName(stageAt(i));
      // What is kept is the very same object.
      if (kept) {
        EXPECT_TRUE(doc.results().reports.identical(stageAt(i), old.results.reports));
      }
    }
    const auto first = firstInvalidatedStage(old, doc.state());
    EXPECT_EQ(first.has_value(), c.kept != kAllStages);
    if (first) {
      EXPECT_EQ(before(*first), c.kept);
    }
  }
}

TEST(Invalidation, SettingAStageResultDropsLaterStagesOnly)
{
  for (int s = 0; s < kStageCount; ++s) {
    const Stage stage = stageAt(s);
    SCOPED_TRACE(stageName(stage));
    Results r = test::fullState().results;
    switch (stage) {
      case Stage::Field:
        r.setField(std::make_shared<const FieldResult>());
        break;
      case Stage::Generatrices:
        r.setGeneratrices(std::make_shared<const Generatrices>());
        break;
      case Stage::Spiral:
        r.setSpiral(std::make_shared<const Trajectory>());
        break;
      case Stage::Process:
        r.setProcess(std::make_shared<const Trajectory>());
        break;
      case Stage::Thermal:
        r.setThermal(std::make_shared<const ThermalStageResult>());
        break;
      case Stage::Kinematics:
        r.setKinematics(std::make_shared<const KinematicsResult>());
        break;
      case Stage::Export:
        r.setExport(std::make_shared<const ExportStageResult>());
        break;
    }
    EXPECT_EQ(r.presentStages(), before(stage) | stageBit(stage));
    for (int i = 0; i < kStageCount; ++i)
      EXPECT_EQ(r.reports.has(stageAt(i)), i < s && i < kStageCount - 1) << i;
  }
}

TEST(Invalidation, ResultsStoredInsideATransactionSurviveItsCommit)
{
  Document doc(test::fullState());
  const auto oldField = doc.results().field;
  auto field = std::make_shared<const FieldResult>(FieldResult{"geodesic_distance", "new part", {1.0, 2.0}});
  {
    Document::Transaction t(doc, "Import and prepare");
    Part p = *doc.part();
    p.mesh = std::make_shared<const TriangleMesh>(test::tetrahedron(2.0));
    doc.setPart(p);
    EXPECT_EQ(doc.results().presentStages(), 0u);
    doc.setField(field);
    t.commit();
  }
  EXPECT_EQ(doc.results().field, field);
  EXPECT_EQ(doc.results().presentStages(), stageBit(Stage::Field));
  doc.undo();
  EXPECT_EQ(doc.results().field, oldField);
  EXPECT_EQ(doc.results().presentStages(), kAllStages);
}

TEST(Invalidation, InvalidateFromIsNotAnUndoStep)
{
  Document doc(test::fullState());
  doc.invalidateFrom(Stage::Process);
  EXPECT_EQ(doc.results().presentStages(), before(Stage::Process));
  EXPECT_FALSE(doc.canUndo());
  EXPECT_FALSE(doc.isModified());
  doc.clearResults();
  EXPECT_EQ(doc.results().presentStages(), 0u);
}

TEST(Invalidation, StageNamesRoundTrip)
{
  for (int i = 0; i < kStageCount; ++i) EXPECT_EQ(parseStageName(stageName(stageAt(i))), stageAt(i));
  EXPECT_FALSE(parseStageName("fields").has_value());
  EXPECT_EQ(stagesFrom(Stage::Kinematics), stageBit(Stage::Kinematics) | stageBit(Stage::Export));
}

}  // namespace
}  // namespace spira
