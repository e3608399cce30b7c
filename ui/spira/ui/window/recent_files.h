#pragma once

#include <QObject>
#include <QStringList>

class QMenu;

namespace spira::ui {

// The File > Recent Files list: most recent first, at most kMaxEntries, kept in QSettings so it
// survives restarts. Files that no longer exist are dropped when the menu is rebuilt.
class RecentFiles : public QObject {
  Q_OBJECT

 public:
  static constexpr int kMaxEntries = 8;

  // Fills `menu` (owned by the caller) and keeps it current.
  explicit RecentFiles(QMenu* menu, QObject* parent = nullptr);

  void add(const QString& path);
  void remove(const QString& path);
  void clear();
  QStringList files() const;

 signals:
  void openRequested(const QString& path);

 private:
  void store(const QStringList& files);
  void rebuildMenu();
  QMenu* menu_;
};

}  // namespace spira::ui
