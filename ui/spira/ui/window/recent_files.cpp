#include "spira/ui/window/recent_files.h"

#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace spira::ui {

namespace {

const char* const kSettingsKey = "recentFiles";

}  // namespace

RecentFiles::RecentFiles(QMenu* menu, QObject* parent) : QObject(parent), menu_(menu)
{
  // Rebuild on opening rather than only on change: files deleted since are left out.
  connect(menu_, &QMenu::aboutToShow, this, &RecentFiles::rebuildMenu);
  rebuildMenu();
}

QStringList RecentFiles::files() const
{
  QStringList list = QSettings().value(kSettingsKey).toStringList();
  list.removeAll(QString());
  return list.mid(0, kMaxEntries);
}

void RecentFiles::store(const QStringList& list)
{
  QSettings().setValue(kSettingsKey, QStringList(list.mid(0, kMaxEntries)));
  // Queued: store() often runs inside a menu action's triggered() signal, and rebuilding deletes
  // that action.
  QMetaObject::invokeMethod(this, &RecentFiles::rebuildMenu, Qt::QueuedConnection);
}

void RecentFiles::add(const QString& path)
{
  const QString absolute = QFileInfo(path).absoluteFilePath();
  QStringList list = files();
  list.removeAll(absolute);
  list.prepend(absolute);
  store(list);
}

void RecentFiles::remove(const QString& path)
{
  QStringList list = files();
  list.removeAll(QFileInfo(path).absoluteFilePath());
  store(list);
}

void RecentFiles::clear()
{
  store({});
}

void RecentFiles::rebuildMenu()
{
  menu_->clear();
  int n = 0;
  for (const QString& path : files()) {
    if (!QFileInfo::exists(path)) continue;
    ++n;
    // &1..&8 give each entry a keyboard accelerator.
    QAction* a = menu_->addAction(QStringLiteral("&%1  %2").arg(n).arg(QFileInfo(path).fileName()));
    a->setToolTip(QDir::toNativeSeparators(path));
    a->setStatusTip(QDir::toNativeSeparators(path));
    a->setData(path);
    connect(a, &QAction::triggered, this, [this, path] { emit openRequested(path); });
  }
  if (n == 0) {
    menu_->addAction(tr("No recent files"))->setEnabled(false);
    return;
  }
  menu_->addSeparator();
  connect(menu_->addAction(tr("Clear Recent Files")), &QAction::triggered, this, &RecentFiles::clear);
}

}  // namespace spira::ui
