// How the window behaves around the document: keyboard shortcuts, cancelled imports, layout
// kept between sessions, and the title following the file and its unsaved changes.
#include <QAction>
#include <QDockWidget>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

#include "builtin_plugins.h"

#include "spira/document/document.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;

TEST(WindowBehaviour, KeyboardShortcutsImportUndoRedoAndFit)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  const ui::Actions& a = w.actions();
  EXPECT_EQ(a.importPart->shortcut(), QKeySequence("Ctrl+I"));
  EXPECT_EQ(a.openProject->shortcut(), QKeySequence("Ctrl+O"));
  EXPECT_EQ(a.save->shortcut(), QKeySequence("Ctrl+S"));
  EXPECT_EQ(a.undo->shortcut(), QKeySequence("Ctrl+Z"));
  EXPECT_TRUE(a.redo->shortcuts().contains(QKeySequence("Ctrl+Shift+Z")));
  EXPECT_TRUE(a.redo->shortcuts().contains(QKeySequence("Ctrl+Y")));
  EXPECT_EQ(a.fitView->shortcut(), QKeySequence("F"));

  TempDir dir;
  showAndWait(w);
  w.activateWindow();
  ASSERT_TRUE(QTest::qWaitForWindowActive(&w, 5000));
  ASSERT_TRUE(openAndWait(w, qpath(writeOpenCylinderStl(dir.path()))));
  QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
  EXPECT_EQ(doc.part(), nullptr);
  QTest::keyClick(&w, Qt::Key_Y, Qt::ControlModifier);
  EXPECT_NE(doc.part(), nullptr);
  QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
  QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
  EXPECT_NE(doc.part(), nullptr);
  QSignalSpy fit(a.fitView, &QAction::triggered);
  QTest::keyClick(&w, Qt::Key_F);
  EXPECT_EQ(fit.count(), 1);
}

TEST(WindowBehaviour, CancelledImportLeavesTheDocumentUnchanged)
{
  TempDir dir;
  const QString stl = qpath(writeOpenCylinderStl(dir.path()));
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  const auto revision = doc.revision();
  QSignalSpy opened(&w, &MainWindow::fileOpened);
  w.importPartFile(stl);
  ASSERT_TRUE(w.busy());
  w.findChild<ui::TaskRunner*>()->cancel();  // what the progress dialog's Cancel does
  w.waitUntilIdle();
  ASSERT_EQ(opened.count(), 1);
  EXPECT_FALSE(opened.at(0).at(1).toBool());
  EXPECT_EQ(doc.part(), nullptr);
  EXPECT_EQ(doc.revision(), revision);
  EXPECT_FALSE(doc.canUndo());
  EXPECT_TRUE(w.logPanel()->text(w.logPanel()->count() - 1).contains("cancelled"));

  ASSERT_TRUE(openAndWait(w, stl));  // and the next import works
  EXPECT_NE(doc.part(), nullptr);
}

TEST(WindowBehaviour, LayoutIsRestoredInTheNextSession)
{
  {
    Document doc;
    MainWindow w(doc, builtinRegistry());
    showAndWait(w);
    w.resize(1100, 700);
    w.findChild<QDockWidget*>("messagesDock")->hide();
    w.actions().showEdges->setChecked(true);
    w.close();
  }
  Document doc;
  MainWindow w(doc, builtinRegistry());
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  EXPECT_EQ(w.size(), QSize(1100, 700));
  EXPECT_FALSE(w.findChild<QDockWidget*>("messagesDock")->isVisible());
  EXPECT_TRUE(w.findChild<QDockWidget*>("documentDock")->isVisible());
  EXPECT_TRUE(w.actions().showEdges->isChecked());
}

TEST(WindowBehaviour, TitleNamesTheFileAndMarksUnsavedChanges)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  EXPECT_EQ(w.windowTitle(), "Untitled[*]");
  EXPECT_FALSE(w.isWindowModified());
  Part part;
  part.name = "tube";
  part.mesh = std::make_shared<const TriangleMesh>();
  doc.setPart(part, "Import Part");  // an edit made elsewhere shows up all the same
  EXPECT_TRUE(w.isWindowModified());
  EXPECT_EQ(w.actions().undo->text(), "&Undo Import Part");
  ASSERT_TRUE(w.saveProjectAs(qpath(dir / "tube.spira")));
  EXPECT_EQ(w.windowTitle(), "tube.spira[*]");
  EXPECT_FALSE(w.isWindowModified());
  w.actions().undo->trigger();
  EXPECT_TRUE(w.isWindowModified());
  // Not interactive: saving without a file name does not ask, and fails.
  Document other;
  MainWindow w2(other, builtinRegistry(), MainWindowOptions{false, false});
  EXPECT_FALSE(w2.saveProject());
}

}  // namespace
}  // namespace spira::test
