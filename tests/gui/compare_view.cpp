// The strategy comparison window: two strategies' deposit-height maps side by side on one colour
// scale and one camera, from a comparison written to files (read back exactly) and from a run on
// the document's part in the background.
#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include "builtin_plugins.h"
#include "spira/base/atomic_file.h"
#include "spira/base/units.h"
#include "spira/document/document.h"
#include "spira/pipeline/comparison_reader.h"
#include "spira/ui/charts/compare_view.h"
#include "spira/ui/views/color_maps.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::CompareView;
using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;

// Two made-up strategies on a unit of known points: a 3-turn helix (one spiral) and 4 rings
// (planar layers), with heights that are a known function of the point.
Comparison madeUp()
{
  Comparison c;
  c.h = 2.0, c.hMin = 1.8, c.hMax = 2.2, c.tolerance = 0.01;
  StrategyOutcome helix;
  helix.strategy = "decomposer.isovalue";
  helix.kind = "ctpp";
  helix.ran = helix.feasible = true;
  helix.paths = 1;
  helix.revolutions = 3;
  for (int i = 0; i < 90; ++i) {
    const double a = 2.0 * kPi * i / 30.0;
    helix.points.emplace_back(30.0 * std::cos(a), 30.0 * std::sin(a), 0.2 * i);
    helix.heights.push_back(1.85 + 0.003 * i);
  }
  StrategyOutcome rings;
  rings.strategy = "planar_2.5d";
  rings.kind = "planar";
  rings.ran = true;
  rings.revolutions = 4;
  for (int l = 0; l < 4; ++l)
    for (int i = 0; i < 20; ++i) {
      const double a = 2.0 * kPi * i / 20.0;
      rings.points.emplace_back(30.0 * std::cos(a), 30.0 * std::sin(a), 5.0 * l);
      rings.heights.push_back(l == 3 ? 2.6 : 2.0);
      rings.outside += l == 3;
    }
  StrategyOutcome failed;
  failed.strategy = "decomposer.geodesic";
  failed.failure = "the part has no closure point";
  c.strategies = {helix, failed, rings};
  return c;
}

TEST(CompareView, ShowsTwoStrategiesFromFilesOnOneScaleAndCamera)
{
  TempDir dir;
  const Comparison truth = madeUp();
  writeComparisonFiles(truth, dir.path());
  const Comparison read = readComparison(dir / "compare.csv");
  ASSERT_EQ(read.strategies.size(), 3u);
  EXPECT_DOUBLE_EQ(read.hMax, 2.2);
  EXPECT_EQ(read.strategies[1].failure, "the part has no closure point");
  EXPECT_FALSE(read.strategies[1].ran);
  ASSERT_EQ(read.strategies[2].points.size(), 80u);
  EXPECT_EQ(read.strategies[2].outside, 20u);
  EXPECT_DOUBLE_EQ(read.strategies[0].heights[10], truth.strategies[0].heights[10]);
  EXPECT_LT((read.strategies[0].points[45] - truth.strategies[0].points[45]).norm(), 1e-9);

  Document doc;
  CompareView view(doc, builtinRegistry());
  view.resize(1100, 620);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view, 10000));
  ASSERT_TRUE(view.openFile(qpath(dir / "compare.json")));
  // The first strategy that ran on the left, the baseline on the right.
  EXPECT_EQ(view.strategy(0), 0);
  EXPECT_EQ(view.strategy(1), 2);
  EXPECT_EQ(view.strategyCombo(0)->count(), 3);
  EXPECT_TRUE(view.strategyCombo(0)->itemText(1).endsWith("(failed)"));
  vtkPolyData* left = view.polyData(0);
  vtkPolyData* right = view.polyData(1);
  ASSERT_EQ(left->GetNumberOfPoints(), 90);
  EXPECT_EQ(left->GetNumberOfLines(), 1) << "one spiral is one line";
  ASSERT_EQ(right->GetNumberOfPoints(), 80);
  EXPECT_EQ(right->GetNumberOfVerts(), 80) << "layer contours are dots";
  EXPECT_DOUBLE_EQ(left->GetPointData()->GetScalars()->GetTuple1(10), 1.85 + 0.03);
  // One scale: the process window with its tolerance; one camera for both views.
  EXPECT_DOUBLE_EQ(view.colourRange().first, 1.79);
  EXPECT_DOUBLE_EQ(view.colourRange().second, 2.21);
  EXPECT_DOUBLE_EQ(view.lookupTable()->GetTableRange()[0], 1.79);
  EXPECT_EQ(view.renderer(0)->GetActiveCamera(), view.renderer(1)->GetActiveCamera());
  EXPECT_TRUE(view.legend().visible());
  EXPECT_TRUE(view.summaryLabel(0)->text().contains("feasible"));
  EXPECT_TRUE(view.summaryLabel(1)->text().contains("20 of 80 points outside"))
      << view.summaryLabel(1)->text().toStdString();

  // Picking the failed strategy shows nothing on that side and says why.
  view.setStrategy(0, 1);
  EXPECT_EQ(view.polyData(0)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(view.summaryLabel(0)->text().contains("no closure point"));
  // Files that are not a comparison are refused with the reason.
  std::filesystem::create_directories(dir / "bad");
  writeBytes(dir / "bad" / "compare.csv", "x,y\n1,2\n");
  EXPECT_FALSE(view.openFile(qpath(dir / "bad" / "compare.csv")));
  EXPECT_TRUE(view.statusLabel()->text().contains("strategy,x,y,z,height"))
      << view.statusLabel()->text().toStdString();
}

// Damaged comparison files are refused naming the file and the place, never with the JSON library's
// own text or a crash.
TEST(CompareView, DamagedComparisonFilesAreRefusedWithTheirPlace)
{
  TempDir dir;
  writeComparisonFiles(madeUp(), dir.path());
  const std::string csv = readFile(dir / "compare.csv");
  struct Case {
    std::string json;
    std::string csv;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"{\"h\": 2, \"strategies\": [1, 2]}", csv,
       "compare.json (strategy 1): expected an object, found the number 1"},
      {"{\"strategies\": [{\"strategy\": 5}]}", csv, "(strategy 1): field 'strategy' must be a string"},
      {"{\"strategies\": [{\"revolutions\": 1e30}]}", csv, "field 'revolutions' must be a whole number"},
      {"{\"strategies\": [{\"n_paths\": -3}]}", csv, "field 'n_paths' must be a count from 0, found -3"},
      {"{\"strategies\": [{\"ran\": \"yes\"}]}", csv, "field 'ran' must be true or false"},
      {"{\"h\": 1e999, \"strategies\": []}", csv, "is beyond the range of a double"},
      {"{\"strategies\": [", csv, "compare.json, line 1, column 17: the JSON text ends too early"},
      {"{\"strategies\": []}", "strategy,x,y,z,height\nhelix,1,2,nan,2\n", "compare.csv line 2: 'nan'"},
      {"{\"strategies\": []}", "strategy,x,y,z,height\nhelix,1,2,3," + std::string(100000, '7') + "e\n",
       "compare.csv line 2: '7777"},
  };
  Document doc;
  CompareView view(doc, builtinRegistry());
  for (const Case& c : cases) {
    writeBytes(dir / "compare.json", c.json);
    writeBytes(dir / "compare.csv", c.csv);
    EXPECT_FALSE(view.openFile(qpath(dir / "compare.json"))) << c.json;
    const std::string status = view.statusLabel()->text().toStdString();
    EXPECT_NE(status.find(c.expected), std::string::npos) << status;
    EXPECT_EQ(status.find("json.exception"), std::string::npos) << status;
    EXPECT_LT(status.size(), 600u) << "the message echoes the file";
  }
}

TEST(CompareView, RunsEveryStrategyOnThePartInTheBackground)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(sourceDir() / "resources" / "samples" / "dome.stl")));
  w.actions().compareStrategies->trigger();
  CompareView* view = w.compareView();
  ASSERT_TRUE(waitFor([&] { return view->isVisible(); }, 5000));
  view->resize(1200, 640);
  QSignalSpy ready(view, &CompareView::comparisonReady);
  view->runOnPart();
  EXPECT_TRUE(view->busy());
  // The window stays responsive meanwhile.
  ASSERT_TRUE(waitFor([&] { return !ready.isEmpty(); }, 600000));
  ASSERT_TRUE(ready.first().at(0).toBool()) << view->statusLabel()->text().toStdString();
  const Comparison& c = view->comparison();
  ASSERT_GE(c.strategies.size(), 2u);
  EXPECT_EQ(c.strategies.back().strategy, "planar_2.5d");
  EXPECT_DOUBLE_EQ(c.hMin, 1.8);
  // Each side shows its strategy's points and heights.
  for (int side = 0; side < CompareView::kSides; ++side) {
    const StrategyOutcome& s = c.strategies[static_cast<size_t>(view->strategy(side))];
    ASSERT_TRUE(s.ran) << s.failure;
    ASSERT_EQ(view->polyData(side)->GetNumberOfPoints(), static_cast<vtkIdType>(s.points.size()));
    EXPECT_DOUBLE_EQ(view->polyData(side)->GetPointData()->GetScalars()->GetTuple1(0), s.heights[0]);
  }
  EXPECT_NE(view->strategy(0), view->strategy(1));
  QApplication::processEvents();
  const QImage shot = view->grabViews();
  EXPECT_GT(distinctColours(shot, shot.rect()), 400);
  saveDocScreenshot(shot, "compare-view.png");
}

}  // namespace
}  // namespace spira::test
