#include <functional>
#include <stdexcept>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "document/document_test_data.h"
#include "spira/base/error.h"
#include "spira/document/document.h"

namespace spira {
namespace {

struct EditCase {
  const char* expectedName;
  std::function<void(Document&)> apply;
};

// A document with a part, a cell and settings, and no undo history.
Document& prepared(Document& doc)
{
  doc.setPart(test::samplePart());
  doc.setCell(test::sampleCell());
  doc.setPlanSettings(test::sampleSettings());
  return doc;
}

TEST(UndoRedo, EveryEditKindIsOneNamedStepThatUndoesAndRedoes)
{
  const std::vector<EditCase> cases = {
      {"Import part",
       [](Document& d) {
         Part p;
         p.name = "other";
         p.mesh = std::make_shared<const TriangleMesh>(test::tetrahedron(1.0));
         d.setPart(p);
       }},
      {"Remove part", [](Document& d) { d.clearPart(); }},
      {"Move part",
       [](Document& d) { d.setPartPlacement(transformFromXyzRpy(Vec3(1, 2, 3), Vec3(0, 0, 1))); }},
      {"Choose lower boundary", [](Document& d) { d.setLowerBoundaryOverride(0); }},
      {"Change substrate", [](Document& d) { d.setSubstrate(Substrate::plane(5.0, Vec3(0, 0, -1))); }},
      {"Change cell", [](Document& d) { d.setCell(CellRecord{}); }},
      {"Remove cell", [](Document& d) { d.clearCell(); }},
      {"Change plan settings", [](Document& d) { d.setPlanSettings(PlanSettings{}); }},
      {"Choose decomposer", [](Document& d) { d.setDecomposer("decomposer.envelope_projection"); }},
      {"Choose closure finder", [](Document& d) { d.setClosureFinder("closure.other"); }},
      {"Change process parameters", [](Document& d) { d.setPluginParams("process", ParamSet()); }},
      {"Change travel_speed", [](Document& d) { d.setParam("process", "travel_speed", 12.0); }},
      {"Custom name", [](Document& d) { d.edit("Custom name", [](DocumentState& s) { s.cell.reset(); }); }},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.expectedName);
    Document doc;
    prepared(doc);
    const DocumentState before = doc.snapshot();
    const size_t steps = doc.undoStack().count();
    c.apply(doc);
    const DocumentState after = doc.snapshot();
    EXPECT_NE(after, before);
    EXPECT_EQ(doc.undoStack().count(), steps + 1);
    EXPECT_EQ(doc.undoStack().undoText(), c.expectedName);
    EXPECT_TRUE(doc.canUndo());
    EXPECT_FALSE(doc.canRedo());
    doc.undo();
    EXPECT_EQ(doc.state(), before);
    EXPECT_EQ(doc.undoStack().redoText(), c.expectedName);
    EXPECT_TRUE(doc.canRedo());
    doc.redo();
    EXPECT_EQ(doc.state(), after);
    EXPECT_FALSE(doc.canRedo());
  }
}

TEST(UndoRedo, EditsWithoutPartAreRejectedWithoutStep)
{
  Document doc;
  EXPECT_THROW(doc.setPartPlacement(Transform::Identity()), InputError);
  EXPECT_THROW(doc.setLowerBoundaryOverride(0), InputError);
  doc.setPart(test::samplePart());
  EXPECT_THROW(doc.setLowerBoundaryOverride(-2), InputError);
  EXPECT_EQ(doc.undoStack().count(), 1u);
}

TEST(UndoRedo, TransactionMergesNestedEditsIntoOneStep)
{
  Document doc;
  const DocumentState empty = doc.snapshot();
  {
    Document::Transaction outer(doc, "Set up cell and part");
    doc.setPart(test::samplePart());
    doc.setCell(test::sampleCell());
    {
      Document::Transaction inner(doc, "inner");
      doc.setParam("process", "travel_speed", 9.0);
      doc.edit("lambda", [](DocumentState& s) {
        s.substrate = std::make_shared<const Substrate>(Substrate::plane(2.0));
      });
      inner.commit();
    }
    EXPECT_TRUE(doc.inTransaction());
    EXPECT_EQ(doc.undoStack().count(), 0u);
    outer.commit();
  }
  EXPECT_EQ(doc.undoStack().count(), 1u);
  EXPECT_EQ(doc.undoStack().undoText(), "Set up cell and part");
  EXPECT_EQ(doc.cell()->name, test::sampleCell().name);
  EXPECT_EQ(doc.substrate()->planeZ, 2.0);
  doc.undo();
  EXPECT_EQ(doc.state(), empty);
  EXPECT_FALSE(doc.canUndo());
}

TEST(UndoRedo, UncommittedTransactionRollsBack)
{
  Document doc;
  prepared(doc);
  const DocumentState before = doc.snapshot();
  const size_t steps = doc.undoStack().count();
  {
    Document::Transaction t(doc, "abandoned");
    doc.clearCell();
    doc.setParam("process", "layers", std::int64_t{4});
    EXPECT_EQ(doc.cell(), nullptr);
  }
  EXPECT_EQ(doc.state(), before);
  EXPECT_EQ(doc.undoStack().count(), steps);
  EXPECT_FALSE(doc.inTransaction());
}

TEST(UndoRedo, InnerRollbackKeepsOuterEdits)
{
  Document doc;
  Document::Transaction outer(doc, "outer");
  doc.setCell(test::sampleCell());
  {
    Document::Transaction inner(doc, "inner");
    doc.setPart(test::samplePart());
  }
  EXPECT_EQ(doc.part(), nullptr);
  ASSERT_NE(doc.cell(), nullptr);
  outer.commit();
  EXPECT_EQ(doc.undoStack().count(), 1u);
}

TEST(UndoRedo, ThrowingEditRestoresStateAndPropagates)
{
  Document doc;
  prepared(doc);
  const DocumentState before = doc.snapshot();
  EXPECT_THROW(doc.edit("Broken",
                        [](DocumentState& s) {
                          s.cell.reset();
                          s.part.reset();
                          throw std::runtime_error("boom");
                        }),
               std::runtime_error);
  EXPECT_EQ(doc.state(), before);
  EXPECT_EQ(doc.undoStack().undoText(), "Change plan settings");
  EXPECT_FALSE(doc.inTransaction());
}

TEST(UndoRedo, NewEditClearsRedo)
{
  Document doc;
  doc.setParam("process", "a", 1.0);
  doc.setParam("process", "b", 2.0);
  doc.undo();
  EXPECT_TRUE(doc.canRedo());
  doc.setParam("process", "c", 3.0);
  EXPECT_FALSE(doc.canRedo());
  EXPECT_EQ(doc.undoStack().redoText(), "");
  EXPECT_EQ(doc.undoStack().count(), 2u);
  EXPECT_FALSE(doc.settings()->section("process").has("b"));
  doc.undo();
  doc.undo();
  EXPECT_TRUE(doc.settings()->section("process").values().empty());
}

TEST(UndoRedo, NoOpEditMakesNoStep)
{
  Document doc;
  prepared(doc);
  const size_t steps = doc.undoStack().count();
  doc.setCell(test::sampleCell());  // equal value, new pointer
  doc.setPlanSettings(test::sampleSettings());
  doc.setPart(test::samplePart());
  doc.setSubstrate(Substrate::plane());
  doc.setPluginParams("export.krl", ParamSet());  // empty section equals absent
  doc.edit("Nothing", [](DocumentState&) {});
  EXPECT_EQ(doc.undoStack().count(), steps);
}

TEST(UndoRedo, ModifiedFlagFollowsCleanIndex)
{
  Document doc;
  EXPECT_FALSE(doc.isModified());
  doc.setParam("process", "a", 1.0);
  EXPECT_TRUE(doc.isModified());
  doc.undo();
  EXPECT_FALSE(doc.isModified());
  doc.redo();
  EXPECT_TRUE(doc.isModified());
  doc.markSaved();
  EXPECT_FALSE(doc.isModified());
  EXPECT_EQ(doc.undoStack().cleanIndex(), 1);
  doc.setParam("process", "b", 1.0);
  EXPECT_TRUE(doc.isModified());
  doc.undo();
  EXPECT_FALSE(doc.isModified());
  doc.undo();
  EXPECT_TRUE(doc.isModified());
  // A new edit from here cuts away the saved state: modified whatever we undo or redo.
  doc.setParam("process", "c", 1.0);
  EXPECT_EQ(doc.undoStack().cleanIndex(), -1);
  EXPECT_TRUE(doc.isModified());
  doc.undo();
  EXPECT_TRUE(doc.isModified());
}

TEST(UndoRedo, DepthLimitDropsOldestSteps)
{
  Document doc;
  doc.setUndoLimit(3);
  for (int i = 0; i < 5; ++i) doc.setParam("process", "k" + std::to_string(i), static_cast<double>(i));
  EXPECT_EQ(doc.undoStack().count(), 3u);
  EXPECT_EQ(doc.undoStack().undoText(), "Change k4");
  for (int i = 0; i < 3; ++i) doc.undo();
  EXPECT_FALSE(doc.canUndo());
  const ParamSet left = doc.settings()->section("process");
  EXPECT_EQ(left.values().size(), 2u);  // k0 and k1 can no longer be undone
  EXPECT_TRUE(left.has("k1"));
  // The saved (initial) state was cut away with the oldest steps.
  EXPECT_TRUE(doc.isModified());
}

TEST(UndoRedo, DepthLimitKeepsSavedStateWhenReachable)
{
  UndoStack stack(2);
  DocumentState s;
  stack.push("a", s);
  stack.setClean();  // after step a
  stack.push("b", s);
  stack.push("c", s);  // drops a: the state after a is now index 0
  EXPECT_EQ(stack.count(), 2u);
  EXPECT_EQ(stack.cleanIndex(), 0);
  EXPECT_EQ(stack.text(0), "b");
}

TEST(UndoRedo, MergeKeyMakesOneStepPerDrag)
{
  Document doc;
  const DocumentState before = doc.snapshot();
  for (double v : {1.0, 2.0, 3.0}) doc.setParam("process", "travel_speed", v);
  EXPECT_EQ(doc.undoStack().count(), 1u);
  EXPECT_EQ(doc.settings()->section("process").getDouble("travel_speed"), 3.0);
  doc.setParam("process", "wire_feed", 4.0);
  EXPECT_EQ(doc.undoStack().count(), 2u);
  doc.setParam("process", "travel_speed", 5.0);  // not adjacent to the earlier drag
  EXPECT_EQ(doc.undoStack().count(), 3u);
  doc.markSaved();
  doc.setParam("process", "travel_speed", 6.0);  // never merges across the saved state
  EXPECT_EQ(doc.undoStack().count(), 4u);
  doc.undo();
  EXPECT_FALSE(doc.isModified());
  doc.undo();
  doc.undo();
  doc.undo();
  EXPECT_EQ(doc.state(), before);
}

TEST(UndoRedo, ResultsAreNotStepsButUndoRestoresThem)
{
  Document doc;
  prepared(doc);
  doc.markSaved();
  const size_t steps = doc.undoStack().count();
  const DocumentState full = test::fullState();
  doc.setResults(full.results);
  EXPECT_EQ(doc.undoStack().count(), steps);
  EXPECT_FALSE(doc.isModified());
  const auto generatrices = doc.results().generatrices;

  doc.setParam("decomposer.geodesic", "smoothing", 0.5);  // active decomposer: drops Generatrices+
  EXPECT_EQ(doc.results().generatrices, nullptr);
  EXPECT_NE(doc.results().field, nullptr);
  // The pipeline recomputes after the edit.
  auto recomputed = std::make_shared<const Generatrices>(test::sampleGeneratrices());
  doc.setGeneratrices(recomputed);

  doc.undo();
  EXPECT_EQ(doc.results().generatrices, generatrices);  // the very same object
  EXPECT_EQ(doc.results(), full.results);
  doc.redo();
  EXPECT_EQ(doc.results().generatrices, recomputed);  // results computed after the edit come back
  EXPECT_EQ(doc.results().spiral, nullptr);
}

TEST(UndoRedo, UndoInsideTransactionIsAnInternalError)
{
  Document doc;
  doc.setParam("process", "a", 1.0);
  Document::Transaction t(doc, "t");
  EXPECT_FALSE(doc.canUndo());
  EXPECT_THROW(doc.undo(), InternalError);
  EXPECT_THROW(doc.redo(), InternalError);
}

TEST(UndoRedo, UndoWithEmptyStackIsAnInternalError)
{
  Document doc;
  EXPECT_THROW(doc.undo(), InternalError);
  EXPECT_THROW(doc.redo(), InternalError);
}

}  // namespace
}  // namespace spira
