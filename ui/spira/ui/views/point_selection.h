#pragma once

#include <QObject>

namespace spira::ui {

// The one "selected point" of the window: an index into the shown plan's path (-1: none). The
// charts, the 3D view, the status bar and the messages panel all select through it and follow it,
// so a point picked anywhere is marked everywhere.
class PointSelection : public QObject {
  Q_OBJECT

 public:
  explicit PointSelection(QObject* parent = nullptr) : QObject(parent) {}

  long long index() const { return index_; }
  bool hasSelection() const { return index_ >= 0; }
  // Selects `index` (negative clears); emits changed() only when it differs.
  void select(long long index)
  {
    if (index < 0) index = -1;
    if (index == index_) return;
    index_ = index;
    emit changed(index_);
  }
  void clear() { select(-1); }

 signals:
  void changed(long long index);

 private:
  long long index_ = -1;
};

}  // namespace spira::ui
