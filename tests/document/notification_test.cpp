#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "document/document_test_data.h"
#include "spira/document/document.h"
#include "support/test_support.h"

namespace spira {
namespace {

// Records every notification of a document.
struct Recorder {
  explicit Recorder(Document& doc) : doc_(doc)
  {
    id_ = doc.subscribe([this](const ChangeSet& c) { seen.push_back(c); });
  }
  ~Recorder() { doc_.unsubscribe(id_); }
  const ChangeSet& only() const
  {
    EXPECT_EQ(seen.size(), 1u);
    return seen.back();
  }
  std::uint32_t flags() const { return only().flags; }
  std::vector<ChangeSet> seen;

 private:
  Document& doc_;
  Document::SubscriptionId id_;
};

constexpr std::uint32_t bits(std::initializer_list<Change> changes)
{
  std::uint32_t b = 0;
  for (Change c : changes) b |= static_cast<std::uint32_t>(c);
  return b;
}

TEST(Notifications, EachEditKindSetsItsFlag)
{
  Document doc;
  doc.setParam("process", "x", 1.0);  // the document is modified from here on
  struct Case {
    const char* name;
    std::function<void(Document&)> apply;
    Change expected;
  };
  const std::vector<Case> cases = {
      {"part", [](Document& d) { d.setPart(test::samplePart()); }, Change::Part},
      {"placement", [](Document& d) { d.setPartPlacement(transformFromXyzRpy(Vec3(5, 0, 0), Vec3::Zero())); },
       Change::Part},
      {"substrate", [](Document& d) { d.setSubstrate(Substrate::plane(3.0)); }, Change::Substrate},
      {"cell", [](Document& d) { d.setCell(test::sampleCell()); }, Change::Cell},
      {"settings", [](Document& d) { d.setDecomposer("decomposer.geodesic"); }, Change::Settings},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    Recorder rec(doc);
    c.apply(doc);
    EXPECT_EQ(rec.flags(), bits({c.expected, Change::UndoStack}));
    EXPECT_EQ(rec.only().stages, 0u);
  }
}

TEST(Notifications, SettingsChangeNamesSectionsAndStrategy)
{
  Document doc;
  Recorder rec(doc);
  doc.setParam("process", "travel_speed", 8.0);
  ASSERT_EQ(rec.seen.size(), 1u);
  EXPECT_EQ(rec.seen[0].sections, std::set<std::string>{"process"});
  EXPECT_FALSE(rec.seen[0].strategyChanged);
  doc.setDecomposer("decomposer.geodesic");
  ASSERT_EQ(rec.seen.size(), 2u);
  EXPECT_TRUE(rec.seen[1].sections.empty());
  EXPECT_TRUE(rec.seen[1].strategyChanged);
}

TEST(Notifications, ModifiedFlagOnlyWhenItFlips)
{
  Document doc;
  Recorder rec(doc);
  doc.setParam("process", "a", 1.0);
  doc.setParam("process", "b", 1.0);
  doc.undo();
  doc.undo();
  ASSERT_EQ(rec.seen.size(), 4u);
  EXPECT_TRUE(rec.seen[0].has(Change::Modified));
  EXPECT_FALSE(rec.seen[1].has(Change::Modified));
  EXPECT_FALSE(rec.seen[2].has(Change::Modified));
  EXPECT_TRUE(rec.seen[3].has(Change::Modified));
  EXPECT_EQ(rec.seen[3].flags, bits({Change::Settings, Change::UndoStack, Change::Modified}));
}

TEST(Notifications, NoOpEditsAreSilent)
{
  Document doc;
  doc.setCell(test::sampleCell());
  doc.setSubstrate(Substrate::plane(1.0));
  Recorder rec(doc);
  doc.setCell(test::sampleCell());
  doc.setSubstrate(Substrate::plane(1.0));
  doc.edit("nothing", [](DocumentState&) {});
  doc.setResults(doc.results());
  doc.invalidateFrom(Stage::Field);  // nothing to drop
  doc.markSaved();
  doc.markSaved();  // already clean
  {
    Document::Transaction t(doc, "rolled back");
    doc.clearCell();
  }
  EXPECT_EQ(rec.seen.size(), 1u);  // only the first markSaved (Modified flipped)
  EXPECT_EQ(rec.flags(), bits({Change::Modified}));
}

TEST(Notifications, TransactionNotifiesOnceAtCommit)
{
  Document doc;
  Recorder rec(doc);
  Document::Transaction t(doc, "setup");
  doc.setPart(test::samplePart());
  doc.setCell(test::sampleCell());
  EXPECT_TRUE(rec.seen.empty());
  t.commit();
  EXPECT_EQ(rec.flags(), bits({Change::Part, Change::Cell, Change::UndoStack, Change::Modified}));
}

TEST(Notifications, ResultsNameTheirStages)
{
  Document doc;
  doc.setResults(test::fullState().results);
  Recorder rec(doc);
  doc.setSpiral(std::make_shared<const Trajectory>(test::sampleTrajectory(3)));
  // New spiral; process, kinematics, export results and the spiral..export reports dropped.
  EXPECT_EQ(rec.flags(), bits({Change::Results}));
  EXPECT_EQ(rec.only().stages, stagesFrom(Stage::Spiral));
  rec.seen.clear();
  doc.setParam("process", "travel_speed", 2.0);  // process stage already empty: nothing to drop
  EXPECT_EQ(rec.only().stages, 0u);
  EXPECT_FALSE(rec.only().has(Change::Results));
  rec.seen.clear();
  doc.setSubstrate(Substrate::plane(1.0));
  EXPECT_EQ(rec.flags(), bits({Change::Substrate, Change::Results, Change::UndoStack}));
  EXPECT_EQ(rec.only().stages,
            stageBit(Stage::Field) | stageBit(Stage::Generatrices) | stageBit(Stage::Spiral));
}

TEST(Notifications, FileOperationsReportPathAndModified)
{
  test::TempDir dir;
  Document doc;
  doc.setCell(test::sampleCell());
  Recorder rec(doc);
  doc.saveAs(dir / "a.spira");
  EXPECT_EQ(rec.flags(), bits({Change::FilePath, Change::Modified}));
  rec.seen.clear();
  doc.save();  // same path, clean already
  EXPECT_TRUE(rec.seen.empty());
  doc.reset();
  const std::uint32_t all = bits({Change::Part, Change::Substrate, Change::Cell, Change::Settings,
                                  Change::Results, Change::UndoStack, Change::Modified, Change::FilePath});
  EXPECT_EQ(rec.flags(), all);
  EXPECT_EQ(rec.only().stages, kAllStages);
  rec.seen.clear();
  doc.open(dir / "a.spira");
  EXPECT_EQ(rec.flags(), all);
}

TEST(Notifications, UnsubscribeStopsCallbacksEvenFromInsideOne)
{
  Document doc;
  int first = 0, second = 0;
  Document::SubscriptionId idSecond = 0;
  Document::SubscriptionId idFirst = doc.subscribe([&](const ChangeSet&) {
    ++first;
    doc.unsubscribe(idFirst);   // itself
    doc.unsubscribe(idSecond);  // and a later one, before it runs
  });
  idSecond = doc.subscribe([&](const ChangeSet&) { ++second; });
  doc.setParam("process", "a", 1.0);
  doc.setParam("process", "b", 1.0);
  EXPECT_EQ(first, 1);
  EXPECT_EQ(second, 0);
}

TEST(Notifications, CallbackMayEditTheDocument)
{
  Document doc;
  std::vector<std::uint32_t> seen;
  doc.subscribe([&](const ChangeSet& c) {
    seen.push_back(c.flags);
    if (c.has(Change::Cell) && !doc.settings()->section("process").has("auto"))
      doc.setParam("process", "auto", true, "Follow cell");
  });
  doc.setCell(test::sampleCell());
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_TRUE(seen[1] & static_cast<std::uint32_t>(Change::Settings));
  EXPECT_EQ(doc.undoStack().count(), 2u);
  EXPECT_EQ(doc.undoStack().undoText(), "Follow cell");
}

TEST(Notifications, RevisionCountsStateChanges)
{
  Document doc;
  const auto r0 = doc.revision();
  doc.setParam("process", "a", 1.0);
  doc.setField(std::make_shared<const FieldResult>(FieldResult{"k", "s", {1.0}}));
  doc.undo();
  doc.setCell(CellRecord());
  doc.setCell(CellRecord());  // no-op
  EXPECT_EQ(doc.revision(), r0 + 4);
}

}  // namespace
}  // namespace spira
