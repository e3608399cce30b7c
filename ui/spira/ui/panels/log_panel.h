#pragma once

#include <QDockWidget>
#include <QString>

class QListWidget;

namespace spira::ui {

enum class LogLevel { Info, Warning, Error };

// The messages dock: what Spira did and what went wrong, newest at the bottom, each line with
// the time. Errors are red and carry their hint (what the user can do) on a second line.
class LogPanel : public QDockWidget {
  Q_OBJECT

 public:
  explicit LogPanel(QWidget* parent = nullptr);

  void info(const QString& message);
  void warning(const QString& message, const QString& hint = {});
  void error(const QString& message, const QString& hint = {});
  void add(LogLevel level, const QString& message, const QString& hint = {});
  void clear();

  int count() const;
  LogLevel level(int row) const;
  // The entry as shown: "[hh:mm:ss] message", and "Hint: ..." on the next line when there is one.
  QString text(int row) const;
  // The list of entries (its items carry the data a message names, e.g. a path point).
  QListWidget* list() const { return list_; }

 private:
  void showContextMenu(const QPoint& pos);
  QListWidget* list_;
};

}  // namespace spira::ui
