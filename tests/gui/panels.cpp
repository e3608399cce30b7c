// The small panels: messages (levels, timestamps, hints) and the recent-files list.
#include <QApplication>
#include <QFile>
#include <QMenu>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>

#include <gtest/gtest.h>

#include "spira/ui/panels/log_panel.h"
#include "spira/ui/window/recent_files.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::LogLevel;
using spira::ui::LogPanel;
using spira::ui::RecentFiles;

TEST(LogPanel, EntriesCarryTimeLevelAndHint)
{
  LogPanel log;
  log.info("Imported cylinder.stl");
  log.warning("Mesh check: 2 x degenerate_face.");
  log.error("cannot read part.stl: truncated", "Export the STL again from your CAD tool.");
  ASSERT_EQ(log.count(), 3);
  EXPECT_EQ(log.level(0), LogLevel::Info);
  EXPECT_EQ(log.level(1), LogLevel::Warning);
  EXPECT_EQ(log.level(2), LogLevel::Error);
  const QRegularExpression stamped(R"(^\[\d\d:\d\d:\d\d\] )");
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(stamped.match(log.text(i)).hasMatch()) << log.text(i).toStdString();
  EXPECT_TRUE(log.text(2).endsWith(
      "cannot read part.stl: truncated\n    Hint: Export the STL again from your CAD tool."));
  EXPECT_FALSE(log.text(0).contains("Hint"));
  log.clear();
  EXPECT_EQ(log.count(), 0);
}

TEST(RecentFiles, MostRecentFirstWithoutDuplicatesAtMostEight)
{
  TempDir dir;
  QMenu menu;
  RecentFiles recent(&menu);
  recent.clear();
  QStringList paths;
  for (int i = 0; i < 10; ++i) {
    const auto file = dir / ("part" + std::to_string(i) + ".stl");
    writeBytes(file, "solid x\nendsolid x\n");
    paths << qpath(file);
    recent.add(paths.back());
  }
  QStringList files = recent.files();
  ASSERT_EQ(files.size(), RecentFiles::kMaxEntries);
  EXPECT_EQ(files.front(), paths[9]);
  EXPECT_EQ(files.back(), paths[2]);

  recent.add(paths[5]);  // again: moves to the front, no duplicate
  files = recent.files();
  EXPECT_EQ(files.size(), RecentFiles::kMaxEntries);
  EXPECT_EQ(files.front(), paths[5]);
  EXPECT_EQ(files.count(paths[5]), 1);

  // Kept in the settings, so a new list (the next session) sees them.
  QMenu otherMenu;
  RecentFiles nextSession(&otherMenu);
  EXPECT_EQ(nextSession.files(), files);

  // The menu lists files that still exist, numbered, and a clear entry.
  QFile::remove(paths[9]);
  emit menu.aboutToShow();
  QApplication::processEvents();
  QStringList entries;
  for (QAction* a : menu.actions()) {
    if (!a->isSeparator()) entries << a->text();
  }
  ASSERT_EQ(entries.size(), RecentFiles::kMaxEntries);  // 7 files + "Clear Recent Files"
  EXPECT_EQ(entries.front(), "&1  part5.stl");
  EXPECT_EQ(entries.back(), "Clear Recent Files");

  QSignalSpy opened(&recent, &RecentFiles::openRequested);
  menu.actions().front()->trigger();
  ASSERT_EQ(opened.count(), 1);
  EXPECT_EQ(opened.at(0).at(0).toString(), paths[5]);

  recent.clear();
  EXPECT_TRUE(recent.files().isEmpty());
}

}  // namespace
}  // namespace spira::test
