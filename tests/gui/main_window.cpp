// The main window end to end: import through the window, undo/redo through its actions, failed
// imports, project save/open, and the screenshot path that `spira --screenshot` uses.
#include <QAction>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QStatusBar>
#include <QTextStream>

#include <gtest/gtest.h>

#include "builtin_plugins.h"

#include "spira/document/document.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/ui/panels/document_tree.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/main_window.h"
#include "spira/ui/window/recent_files.h"
#include "spira/ui/window/screenshot.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::LogLevel;
using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;

constexpr size_t kTriangles = 2 * kCylinderSegments * kCylinderRings;
constexpr size_t kVertices = kCylinderSegments * (kCylinderRings + 1);

QString childValue(QTreeWidgetItem* item, const QString& key)
{
  for (int i = 0; item && i < item->childCount(); ++i) {
    if (item->child(i)->text(0) == key) return item->child(i)->text(1);
  }
  return QStringLiteral("<missing>");
}

bool statusShows(MainWindow& w, const QString& text)
{
  for (QLabel* label : w.statusBar()->findChildren<QLabel*>()) {
    if (label->text().contains(text)) return true;
  }
  return false;
}

TEST(MainWindow, ImportShowsThePartAndUndoRedoGoThroughTheActions)
{
  TempDir dir;
  const QString stl = qpath(writeOpenCylinderStl(dir.path()));
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  EXPECT_FALSE(w.actions().undo->isEnabled());
  EXPECT_FALSE(w.sceneView()->hasPart());

  ASSERT_TRUE(openAndWait(w, stl)) << w.lastErrorMessage().toStdString();
  ASSERT_TRUE(doc.part());
  EXPECT_EQ(doc.part()->mesh->faceCount(), kTriangles);
  EXPECT_EQ(doc.part()->mesh->vertexCount(), kVertices);  // welded: shared vertices
  EXPECT_TRUE(doc.isModified());
  EXPECT_TRUE(w.sceneView()->hasPart());

  QTreeWidgetItem* part = w.documentTree()->section("Part");
  ASSERT_NE(part, nullptr);
  EXPECT_EQ(part->text(1), "cylinder");
  EXPECT_EQ(childValue(part, "Type"), "open");
  EXPECT_EQ(childValue(part, "Boundary loops"), "2");
  EXPECT_EQ(childValue(part, "Triangles").remove(',').toInt(), static_cast<int>(kTriangles));
  EXPECT_TRUE(statusShows(w, "Units: mm"));
  EXPECT_TRUE(statusShows(w, QLocale().toString(static_cast<qulonglong>(kTriangles))));

  EXPECT_TRUE(w.actions().undo->isEnabled());
  EXPECT_EQ(w.actions().undo->text(), "&Undo Import Part");
  EXPECT_FALSE(w.actions().redo->isEnabled());
  const auto mesh = doc.part()->mesh;

  w.actions().undo->trigger();
  EXPECT_EQ(doc.part(), nullptr);
  EXPECT_FALSE(w.sceneView()->hasPart());
  EXPECT_EQ(w.documentTree()->section("Part")->text(1), "none (File > Import Part...)");
  EXPECT_TRUE(statusShows(w, "No part"));
  EXPECT_EQ(w.actions().redo->text(), "&Redo Import Part");
  EXPECT_FALSE(w.actions().undo->isEnabled());

  w.actions().redo->trigger();
  ASSERT_TRUE(doc.part());
  EXPECT_EQ(doc.part()->mesh, mesh);  // the same immutable mesh comes back, not a copy
  EXPECT_TRUE(w.sceneView()->hasPart());
  EXPECT_EQ(w.documentTree()->section("Part")->text(1), "cylinder");
}

TEST(MainWindow, FailedImportLeavesTheDocumentUnchangedAndShowsErrorAndHint)
{
  TempDir dir;
  const QString good = qpath(writeOpenCylinderStl(dir.path()));
  writeBytes(dir / "broken.stl", "solid broken\n facet normal 0 0 1\n  outer loop\n   vertex 0 0\n");
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, good));
  const auto partBefore = doc.part();
  const auto revisionBefore = doc.revision();
  const int logBefore = w.logPanel()->count();

  EXPECT_FALSE(openAndWait(w, qpath(dir / "broken.stl")));
  EXPECT_EQ(doc.part(), partBefore);
  EXPECT_EQ(doc.revision(), revisionBefore);
  EXPECT_EQ(w.actions().undo->text(), "&Undo Import Part");  // still only the first import
  EXPECT_FALSE(w.lastErrorMessage().isEmpty());
  EXPECT_FALSE(w.lastErrorHint().isEmpty());
  ASSERT_GT(w.logPanel()->count(), logBefore);
  const int last = w.logPanel()->count() - 1;
  EXPECT_EQ(w.logPanel()->level(last), LogLevel::Error);
  EXPECT_TRUE(w.logPanel()->text(last).contains("Hint: " + w.lastErrorHint()));

  EXPECT_FALSE(openAndWait(w, qpath(dir / "missing.stl")));
  EXPECT_FALSE(openAndWait(w, qpath(dir / "part.unknownformat")));
  EXPECT_EQ(doc.part(), partBefore);
  EXPECT_EQ(doc.revision(), revisionBefore);
}

// Files that crashed or hung the import (docs in tests/data/hostile/*/README.md): each is refused
// with a message naming it, the document keeps its part and the window stays up and usable.
TEST(MainWindow, HostileFilesAreRefusedWithAMessageAndTheWindowStaysUp)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(writeOpenCylinderStl(dir.path()))));
  const auto partBefore = doc.part();
  const std::filesystem::path hostile = sourceDir() / "tests/data/hostile";
  for (const char* file : {"step/wrong_type_crash.step", "step/unresolved_face.step", "ply/cut_in_format.ply",
                           "ply/no_end_header.ply", "ply/huge_vertex_count.ply", "ply/index_out_of_range.ply",
                           "ply/truncated_faces.ply"}) {
    const std::filesystem::path path = hostile / file;
    EXPECT_FALSE(openAndWait(w, qpath(path))) << file;
    EXPECT_TRUE(w.lastErrorMessage().contains(QString::fromStdString(path.filename().string())))
        << file << ": " << w.lastErrorMessage().toStdString();
    EXPECT_EQ(doc.part(), partBefore) << file;
    EXPECT_TRUE(w.isVisible()) << file;
  }
  // Still usable: a good part imports after them.
  EXPECT_TRUE(openAndWait(w, qpath(writeOpenCylinderStl(dir.path()))));
}

TEST(MainWindow, SavedProjectOpensWithTheSamePartAndIsRemembered)
{
  TempDir dir;
  const QString stl = qpath(writeOpenCylinderStl(dir.path()));
  const QString project = qpath(dir / "job.spira");
  {
    Document doc;
    MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
    showAndWait(w);
    ASSERT_TRUE(openAndWait(w, stl));
    EXPECT_TRUE(w.isWindowModified());
    ASSERT_TRUE(w.saveProjectAs(qpath(dir / "job")));  // the extension is added
    EXPECT_TRUE(QFile::exists(project));
    EXPECT_FALSE(doc.isModified());
    EXPECT_FALSE(w.isWindowModified());
    EXPECT_EQ(w.windowTitle(), "job.spira[*]");
  }
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, project));
  ASSERT_TRUE(doc.part());
  EXPECT_EQ(doc.part()->mesh->faceCount(), kTriangles);
  EXPECT_EQ(doc.part()->name, "cylinder");
  EXPECT_FALSE(doc.canUndo());
  EXPECT_TRUE(w.sceneView()->hasPart());
  EXPECT_EQ(childValue(w.documentTree()->section("Part"), "Type"), "open");  // report recomputed
  const QStringList recent = w.recentFiles()->files();
  ASSERT_GE(recent.size(), 2);
  EXPECT_EQ(recent[0], project);
  EXPECT_EQ(recent[1], stl);

  writeBytes(dir / "damaged.spira", "SPIRAPRJ-not-really");
  EXPECT_FALSE(openAndWait(w, qpath(dir / "damaged.spira")));
  EXPECT_EQ(doc.part()->mesh->faceCount(), kTriangles);
  EXPECT_EQ(w.logPanel()->level(w.logPanel()->count() - 1), LogLevel::Error);
}

// Settings that contradict each other (here the travel-speed limits, crossed) can only come from a
// file: the project opens, the contradiction is a warning naming the fix, and nothing throws out of
// the views that read the settings.
TEST(MainWindow, ProjectWithCrossedLimitsOpensWithAWarning)
{
  TempDir dir;
  const std::filesystem::path project = dir / "crossed.spira";
  {
    Document doc;
    Part part;
    part.name = "cylinder";
    part.mesh = std::make_shared<const TriangleMesh>(makeOpenCylinder(50.0, 60.0, 90, 30));
    doc.setPart(part);
    doc.setParam(PlanSettings::kProcessSection, "ts_min", 30.0);
    doc.setParam(PlanSettings::kProcessSection, "ts_max", 10.0);
    doc.saveAs(project);
  }
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(project))) << w.lastErrorMessage().toStdString();
  ASSERT_TRUE(doc.part());
  bool warned = false;
  for (int i = 0; i < w.logPanel()->count(); ++i)
    warned = warned || (w.logPanel()->level(i) == LogLevel::Warning &&
                        w.logPanel()->text(i).contains("travel-speed limits are crossed (ts_min >= ts_max)"));
  EXPECT_TRUE(warned);
}

TEST(MainWindow, ScreenshotShowsThePartInTheCentreOfTheView)
{
  TempDir dir;
  const QString stl = qpath(writeOpenCylinderStl(dir.path()));
  const QString png = qpath(dir / "shot.png");
  QString errors;
  QTextStream err(&errors);
  ASSERT_EQ(ui::takeScreenshot({stl, png}, builtinRegistry(), err), kExitOk) << errors.toStdString();
  QImage shot(png);
  ASSERT_FALSE(shot.isNull());
  EXPECT_EQ(shot.size(), QSize(1280, 800));

  // The same window without a part, captured the same way, is the reference background.
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  const QImage empty = w.captureImage();
  ASSERT_EQ(empty.size(), shot.size());
  // For looking at the pictures: SPIRA_GUI_SCREENSHOT_DIR=/some/folder keeps both.
  const QString keep = qEnvironmentVariable("SPIRA_GUI_SCREENSHOT_DIR");
  if (!keep.isEmpty()) {
    empty.save(keep + "/empty_window.png");
    shot.save(keep + "/cylinder_window.png");
  }
  const QRect view = sceneRect(w);
  ASSERT_GT(view.width(), 400);
  ASSERT_GT(view.height(), 300);

  EXPECT_GT(distinctColours(shot, view), 500);  // shading, a gradient, lines: not a flat fill
  const QRect centre(view.center() - QPoint(40, 40), QSize(80, 80));
  EXPECT_GT(meanDifference(shot, empty, centre), 12.0) << "no part pixels in the centre of the view";
  // The view's corners show background and plate, not the part.
  const QRect corner(view.topRight() - QPoint(60, -10), QSize(50, 50));
  EXPECT_LT(meanDifference(shot, empty, corner), 3.0);

  // Unreadable input: exit code 3 and a message.
  errors.clear();
  EXPECT_EQ(ui::takeScreenshot({qpath(dir / "none.stl"), png}, builtinRegistry(), err), kExitBadInput);
  EXPECT_TRUE(errors.startsWith("spira: "));
}

}  // namespace
}  // namespace spira::test
